package touchline.security;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;

/**
 * The small robots' message tag (docs/security.md): the first 16 bytes of
 * HMAC-SHA-512(team key, direction ‖ robot id ‖ key-id ‖ counter ‖ payload) (RFC 2104), on the
 * JDK's SHA-512 ({@code java.security.MessageDigest}) with the two key pads hashed once per key,
 * as RFC 2104 section 4 suggests: each tag resumes from copies of the two digests that have
 * hashed K⊕ipad and K⊕opad, so a short datagram costs two or three SHA-512 block compressions
 * instead of the JDK {@code Mac}'s three or four (it hashes the outer pad for every message).
 * The constructor checks the result against the JDK's {@code javax.crypto.Mac} "HmacSHA512"
 * for the key, and {@code MessageTagTest} for every length and many keys. Direction is {@link #TO_ROBOT} ('C') for what
 * the console sends and {@link #FROM_ROBOT} ('R') for what a robot sends, so a robot's datagram
 * reflected back to it never passes. Pure; one instance per thread (a Mac is not thread-safe).
 */
public final class MessageTag {

    public static final byte TO_ROBOT = 'C';
    public static final byte FROM_ROBOT = 'R';
    public static final int TAG_SIZE = 16;

    /** Why a datagram is not authentic, or OK. */
    public enum Check { OK, NO_TAG, TRUNCATED, WRONG_KEY, BAD_TAG }

    private final TeamKey key;
    /** SHA-512 having hashed the 128-byte block K⊕ipad: the inner hash resumes from a copy. */
    private final MessageDigest inner;
    /** SHA-512 having hashed the 128-byte block K⊕opad: the outer hash resumes from a copy. */
    private final MessageDigest outer;
    private final byte[] head = new byte[2 + TeamKey.ID_SIZE + 8];
    /** The inner hash of the last check, reused and wiped after each use. */
    private final byte[] innerHash = new byte[64];
    /** The full HMAC-SHA-512 of the last check, reused (digest into it) and wiped after each use. */
    private final byte[] full = new byte[64];

    public MessageTag(TeamKey key) {
        this.key = key;
        inner = padded(key.secret(), (byte) 0x36);
        outer = padded(key.secret(), (byte) 0x5c);
        System.arraycopy(key.id(), 0, head, 2, TeamKey.ID_SIZE);
        agreesWithTheJdkMac(key);
    }

    /** SHA-512 after one block: the key (32 bytes, under SHA-512's 128-byte block) zero-padded, XOR {@code pad}. */
    private static MessageDigest padded(byte[] secret, byte pad) {
        byte[] block = new byte[128];
        for (int i = 0; i < block.length; i++) {
            block[i] = (byte) ((i < secret.length ? secret[i] : 0) ^ pad);
        }
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-512");
            md.update(block);
            md.clone(); // cloneable here, or the key is refused now rather than a datagram later
            return md;
        } catch (GeneralSecurityException | CloneNotSupportedException e) {
            throw new IllegalStateException("the JDK's SHA-512 is missing or cannot be copied", e);
        } finally {
            java.util.Arrays.fill(block, (byte) 0);
        }
    }

    /** The tag of a fixed message against the JDK's own HmacSHA512: a wrong construction never tags. */
    private void agreesWithTheJdkMac(TeamKey key) {
        byte[] probe = "touchline: the JDK's HMAC and ours agree".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        try {
            Mac jdk = Mac.getInstance("HmacSHA512");
            jdk.init(new SecretKeySpec(key.secret(), "HmacSHA512"));
            mac(FROM_ROBOT, 0x7f, 0x0123456789abcdefL, probe, 0, probe.length);
            jdk.update(head);
            jdk.update(probe);
            boolean same = MessageDigest.isEqual(jdk.doFinal(), full);
            java.util.Arrays.fill(full, (byte) 0);
            if (!same) {
                throw new IllegalStateException("HMAC-SHA-512 from the precomputed pads differs from the JDK's HmacSHA512");
            }
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK's HmacSHA512 is missing", e);
        }
    }

    public TeamKey key() {
        return key;
    }

    /** The 16-byte tag over {@code payload[off, off+len)}. */
    public byte[] tag(byte direction, int robotId, long counter, byte[] payload, int off, int len) {
        mac(direction, robotId, counter, payload, off, len);
        byte[] tag = java.util.Arrays.copyOf(full, TAG_SIZE);
        java.util.Arrays.fill(full, (byte) 0);
        return tag;
    }

    /** The full HMAC into {@link #full}: no array allocated per datagram (the ingest's hot path). */
    private void mac(byte direction, int robotId, long counter, byte[] payload, int off, int len) {
        head[0] = direction;
        head[1] = (byte) robotId;
        Trailer.putLong(head, 2 + TeamKey.ID_SIZE, counter);
        try {
            MessageDigest in = (MessageDigest) inner.clone();
            in.update(head);
            in.update(payload, off, len);
            in.digest(innerHash, 0, innerHash.length);
            MessageDigest out = (MessageDigest) outer.clone();
            out.update(innerHash);
            out.digest(full, 0, full.length);
            java.util.Arrays.fill(innerHash, (byte) 0);
        } catch (java.security.DigestException | CloneNotSupportedException e) {
            throw new IllegalStateException("SHA-512 could not be copied or wrote more than 64 bytes", e);
        }
    }

    /** A new array: payload followed by the 32-byte trailer. */
    public byte[] append(byte direction, int robotId, long counter, byte[] payload) {
        byte[] out = java.util.Arrays.copyOf(payload, payload.length + Trailer.SIZE);
        int at = payload.length;
        System.arraycopy(Trailer.MAGIC, 0, out, at, 4);
        System.arraycopy(key.id(), 0, out, at + 4, TeamKey.ID_SIZE);
        Trailer.putLong(out, at + 8, counter);
        System.arraycopy(tag(direction, robotId, counter, payload, 0, payload.length), 0, out, at + 16, TAG_SIZE);
        return out;
    }

    /** Checks the trailer of a datagram (the counter's order is the caller's: {@link ReplayGuard}). */
    public Check check(byte direction, int robotId, byte[] datagram, Trailer trailer) {
        if (trailer instanceof Trailer.Absent) {
            return Check.NO_TAG;
        }
        if (trailer instanceof Trailer.Truncated) {
            return Check.TRUNCATED;
        }
        Trailer.Present p = (Trailer.Present) trailer;
        int at = p.payloadLength();
        if (!key.sameId(datagram, at + 4)) {
            return Check.WRONG_KEY;
        }
        mac(direction, robotId, p.counter(), datagram, 0, at);
        // constant time, like MessageDigest.isEqual, without copying either side
        int diff = 0;
        for (int i = 0; i < TAG_SIZE; i++) {
            diff |= full[i] ^ datagram[at + 16 + i];
        }
        java.util.Arrays.fill(full, (byte) 0);
        return diff == 0 ? Check.OK : Check.BAD_TAG;
    }
}
