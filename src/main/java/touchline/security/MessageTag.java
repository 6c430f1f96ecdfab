package touchline.security;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import java.security.GeneralSecurityException;

/**
 * The small robots' message tag (docs/security.md), trailer version 2 ("TLA2"): the first 16
 * bytes of HMAC-SHA-256(team key, direction ‖ robot id ‖ [robot's boot] ‖ key-id ‖ counter ‖ payload),
 * computed with the JDK's {@code javax.crypto.Mac} "HmacSHA256" (the firmware: libsodium's
 * crypto_auth_hmacsha256). The {@link Way} is {@link #toRobot} ('C') for what the console sends,
 * bound to the robot's boot the console believes (4 bytes, big-endian, hashed and not sent: a
 * request captured in an earlier boot fails after a reboot), and {@link #FROM_ROBOT} ('R') for
 * what a robot sends (its boot is in its counter), so a robot's datagram reflected back to it
 * never passes. Version 1 ("TLA1", Touchline 0.5) was HMAC-SHA-512: three times the cost per
 * datagram on the console and about twice on a Cortex-M3, for the same 128-bit tag (docs/archive/benchmarks-sessions.md,
 * "Eleventh session"). Pure; one instance per thread (a Mac is not thread-safe).
 */
public final class MessageTag {

    /**
     * Which way a datagram goes: console → robot ('C', bound to the robot's boot) or robot →
     * console ('R').
     */
    public record Way(byte direction, boolean boundToBoot, int robotBoot) { }

    public static final Way FROM_ROBOT = new Way((byte) 'R', false, 0);

    /** Console → robot, for the robot's boot {@code robotBoot} (the high word of its own counter). */
    public static Way toRobot(int robotBoot) {
        return new Way((byte) 'C', true, robotBoot);
    }

    public static final int TAG_SIZE = 16;

    /** Why a datagram is not authentic, or OK. */
    public enum Check { OK, NO_TAG, TRUNCATED, OUTDATED, WRONG_KEY, BAD_TAG }

    private final TeamKey key;
    /**
     * One keyed Mac, used for every tag: {@code doFinal} leaves it ready for the next message.
     * Not a clone per datagram: the clone's allocations (the Mac's and its digest's state) cost
     * the console's ingest more than the HMAC itself under its ZGC (docs/benchmarks.md).
     */
    private final Mac mac;
    private final byte[] head = new byte[2 + 4 + TeamKey.ID_SIZE + 8];
    /** The full HMAC-SHA-256 of the last check, reused (doFinal into it) and wiped after each use. */
    private final byte[] full = new byte[32];

    public MessageTag(TeamKey key) {
        this.key = key;
        try {
            mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key.secret(), "HmacSHA256"));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK's HmacSHA256 is missing", e);
        }
    }

    public TeamKey key() {
        return key;
    }

    /** The 16-byte tag over {@code payload[off, off+len)}. */
    public byte[] tag(Way way, int robotId, long counter, byte[] payload, int off, int len) {
        mac(way, robotId, counter, payload, off, len);
        byte[] tag = java.util.Arrays.copyOf(full, TAG_SIZE);
        java.util.Arrays.fill(full, (byte) 0);
        return tag;
    }

    /** The full HMAC into {@link #full}: no array allocated per datagram (the ingest's hot path). */
    private void mac(Way way, int robotId, long counter, byte[] payload, int off, int len) {
        head[0] = way.direction();
        head[1] = (byte) robotId;
        int at = 2;
        if (way.boundToBoot()) {
            head[2] = (byte) (way.robotBoot() >>> 24);
            head[3] = (byte) (way.robotBoot() >>> 16);
            head[4] = (byte) (way.robotBoot() >>> 8);
            head[5] = (byte) way.robotBoot();
            at = 6;
        }
        System.arraycopy(key.id(), 0, head, at, TeamKey.ID_SIZE);
        Trailer.putLong(head, at + TeamKey.ID_SIZE, counter);
        try {
            mac.update(head, 0, at + TeamKey.ID_SIZE + 8);
            mac.update(payload, off, len);
            mac.doFinal(full, 0);
        } catch (javax.crypto.ShortBufferException e) {
            throw new IllegalStateException("HmacSHA256 wrote more than 32 bytes", e);
        }
    }

    /** A new array: payload followed by the 32-byte trailer (version 2). */
    public byte[] append(Way way, int robotId, long counter, byte[] payload) {
        byte[] out = java.util.Arrays.copyOf(payload, payload.length + Trailer.SIZE);
        int at = payload.length;
        System.arraycopy(Trailer.MAGIC, 0, out, at, 4);
        System.arraycopy(key.id(), 0, out, at + 4, TeamKey.ID_SIZE);
        Trailer.putLong(out, at + 8, counter);
        System.arraycopy(tag(way, robotId, counter, payload, 0, payload.length), 0, out, at + 16, TAG_SIZE);
        return out;
    }

    /** Checks the trailer of a datagram (the counter's order is the caller's: {@link ReplayGuard}). */
    public Check check(Way way, int robotId, byte[] datagram, Trailer trailer) {
        if (trailer instanceof Trailer.Absent) {
            return Check.NO_TAG;
        }
        if (trailer instanceof Trailer.Truncated) {
            return Check.TRUNCATED;
        }
        if (trailer instanceof Trailer.Outdated) {
            return Check.OUTDATED;
        }
        Trailer.Present p = (Trailer.Present) trailer;
        int at = p.payloadLength();
        if (!key.sameId(datagram, at + 4)) {
            return Check.WRONG_KEY;
        }
        mac(way, robotId, p.counter(), datagram, 0, at);
        // constant time, like MessageDigest.isEqual, without copying either side
        int diff = 0;
        for (int i = 0; i < TAG_SIZE; i++) {
            diff |= full[i] ^ datagram[at + 16 + i];
        }
        java.util.Arrays.fill(full, (byte) 0);
        return diff == 0 ? Check.OK : Check.BAD_TAG;
    }
}
