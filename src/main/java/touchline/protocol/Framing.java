package touchline.protocol;

/**
 * The two FUmanoids datagram headers. Robots up to 2014 used the 12-byte legacy header
 * (type 42, flags, alignment, reserved, length); later firmware sends only the 4-byte
 * big-endian length. A console accepts both and answers each robot in its own framing.
 */
public enum Framing {
    LEGACY(12),
    LENGTH_PREFIX(4);

    public static final int MESSAGE_TYPE = 42;

    private final int headerSize;

    Framing(int headerSize) {
        this.headerSize = headerSize;
    }

    public int headerSize() {
        return headerSize;
    }
}
