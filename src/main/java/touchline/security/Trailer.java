package touchline.security;

/**
 * The authentication trailer of the small robots' datagrams (docs/security.md):
 * {@code payload ‖ "TLA2" ‖ key-id (4) ‖ counter (8, big-endian) ‖ tag (16)}. Pure parsing:
 * where the payload ends and what the trailer says, or why there is none. A version-1 trailer
 * ("TLA1": the same layout, tagged with HMAC-SHA-512 by Touchline 0.5 and its firmware) is
 * recognised so that its bytes never reach the decoder (recordings of 0.5 still open) and the
 * user is told to update the robot, but it is never verified.
 */
public sealed interface Trailer {

    int SIZE = 32;
    byte[] MAGIC = {'T', 'L', 'A', '2'};
    /** Version 1's magic (Touchline 0.5): recognised, never verified. */
    byte[] OUTDATED_MAGIC = {'T', 'L', 'A', '1'};

    /** A whole trailer: the payload is {@code datagram[0, payloadLength)}. */
    record Present(int payloadLength, long counter) implements Trailer { }

    /** A whole version-1 trailer (HMAC-SHA-512, Touchline 0.5): the payload is {@code datagram[0, payloadLength)}. */
    record Outdated(int payloadLength) implements Trailer { }

    /** No trailer: the datagram is all payload. */
    record Absent() implements Trailer { }

    /** The magic found, but fewer than 32 bytes from it to the end: a tag cut short. */
    record Truncated(int bytes) implements Trailer { }

    static Trailer of(byte[] d, int length) {
        if (length >= SIZE && magicAt(d, length - SIZE, MAGIC)) {
            return new Present(length - SIZE, getLong(d, length - SIZE + 8));
        }
        if (length >= SIZE && magicAt(d, length - SIZE, OUTDATED_MAGIC)) {
            return new Outdated(length - SIZE);
        }
        for (int back = SIZE - 1; back >= MAGIC.length; back--) {
            if (back <= length && magicAt(d, length - back, MAGIC)) {
                return new Truncated(back);
            }
        }
        return new Absent();
    }

    static Trailer of(byte[] d) {
        return of(d, d.length);
    }

    private static boolean magicAt(byte[] d, int at, byte[] magic) {
        return d[at] == magic[0] && d[at + 1] == magic[1] && d[at + 2] == magic[2] && d[at + 3] == magic[3];
    }

    /** Where the payload ends: before a whole trailer of either version, else the datagram's end. */
    default int payloadLength(int datagramLength) {
        if (this instanceof Present p) {
            return p.payloadLength();
        }
        return this instanceof Outdated o ? o.payloadLength() : datagramLength;
    }

    static long getLong(byte[] d, int at) {
        long v = 0;
        for (int i = 0; i < 8; i++) {
            v = (v << 8) | (d[at + i] & 0xFF);
        }
        return v;
    }

    static void putLong(byte[] d, int at, long v) {
        for (int i = 7; i >= 0; i--) {
            d[at + i] = (byte) v;
            v >>>= 8;
        }
    }
}
