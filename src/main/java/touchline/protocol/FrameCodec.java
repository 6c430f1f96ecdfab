package touchline.protocol;

import java.util.Arrays;

/**
 * Puts the FUmanoids header on a protobuf payload and takes it off again. Pure: no I/O.
 * The framing is detected per datagram: {@code 00 2A} starts a legacy header, anything else
 * must carry a 4-byte big-endian length equal to the rest of the datagram.
 */
public final class FrameCodec {

    /** The Wi-Fi module's buffer: no datagram, header included, may be larger. */
    public static final int MAX_DATAGRAM = 1400;

    private final int maxDatagram;

    public FrameCodec() {
        this(MAX_DATAGRAM);
    }

    public FrameCodec(int maxDatagram) {
        this.maxDatagram = maxDatagram;
    }

    public FrameResult decode(byte[] datagram) {
        return decode(datagram, datagram.length);
    }

    public FrameResult decode(byte[] d, int length) {
        if (length > maxDatagram) {
            return new FrameResult.Malformed("datagram of " + length + " bytes exceeds the " + maxDatagram + "-byte limit");
        }
        if (length >= 2 && d[0] == 0 && d[1] == Framing.MESSAGE_TYPE) {
            if (length < Framing.LEGACY.headerSize()) {
                return new FrameResult.Malformed("truncated legacy header: " + length + " of 12 bytes");
            }
            return payload(Framing.LEGACY, d, length, lengthField(d, 8));
        }
        if (length < Framing.LENGTH_PREFIX.headerSize()) {
            return new FrameResult.Malformed("truncated header: " + length + " bytes");
        }
        return payload(Framing.LENGTH_PREFIX, d, length, lengthField(d, 0));
    }

    private static FrameResult payload(Framing framing, byte[] d, int length, long declared) {
        int header = framing.headerSize();
        if (declared != length - header) {
            return new FrameResult.Malformed((framing == Framing.LEGACY ? "legacy" : "length")
                    + " header says " + declared + " payload bytes, datagram has " + (length - header));
        }
        return new FrameResult.Frame(framing, Arrays.copyOfRange(d, header, length));
    }

    public byte[] encode(Framing framing, byte[] payload) {
        int header = framing.headerSize();
        if (payload.length + header > maxDatagram) {
            throw new IllegalArgumentException("message of " + payload.length + " bytes does not fit in one "
                    + maxDatagram + "-byte datagram");
        }
        byte[] out = new byte[header + payload.length];
        if (framing == Framing.LEGACY) {
            out[1] = Framing.MESSAGE_TYPE;
        }
        int n = payload.length;
        out[header - 4] = (byte) (n >>> 24);
        out[header - 3] = (byte) (n >>> 16);
        out[header - 2] = (byte) (n >>> 8);
        out[header - 1] = (byte) n;
        System.arraycopy(payload, 0, out, header, n);
        return out;
    }

    static long lengthField(byte[] d, int offset) {
        return ((long) (d[offset] & 0xFF) << 24) | ((d[offset + 1] & 0xFF) << 16)
                | ((d[offset + 2] & 0xFF) << 8) | (d[offset + 3] & 0xFF);
    }
}
