package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/** Header checks and little-endian buffers shared by the GameController formats. */
final class WireChecks {

    static final byte[] GAME_STATE_MAGIC = {'R', 'G', 'm', 'e'};
    static final byte[] RETURN_MAGIC = {'R', 'G', 'r', 't'};
    /** The HSL GameController's copy of the true game state for registered monitors. */
    static final byte[] TRUE_DATA_MAGIC = {'R', 'G', 'T', 'D'};
    static final byte[] MONITOR_REQUEST_MAGIC = {'R', 'G', 'T', 'r'};

    private WireChecks() {
    }

    static ByteBuffer writer(int size) {
        return ByteBuffer.allocate(size).order(ByteOrder.LITTLE_ENDIAN);
    }

    static ByteBuffer reader(byte[] datagram) {
        return ByteBuffer.wrap(datagram).order(ByteOrder.LITTLE_ENDIAN);
    }

    /** Null when length and magic are right, else the rejection. */
    static <T> Decoded<T> checkFrame(byte[] datagram, int size, byte[] magic) {
        if (datagram == null || datagram.length != size) {
            return Decoded.rejected(DecodeFailure.WRONG_LENGTH,
                    "expected " + size + " bytes, got " + (datagram == null ? 0 : datagram.length));
        }
        for (int i = 0; i < 4; i++) {
            if (datagram[i] != magic[i]) {
                return Decoded.rejected(DecodeFailure.WRONG_MAGIC, "header is not " + new String(magic,
                        java.nio.charset.StandardCharsets.US_ASCII));
            }
        }
        return null;
    }

    static <T> Decoded<T> wrongVersion(int expected, long got) {
        return Decoded.rejected(DecodeFailure.WRONG_VERSION, "expected version " + expected + ", got " + got);
    }

    static byte[] finish(ByteBuffer b, int size) {
        if (b.position() != size) {
            throw new IllegalStateException("serializer wrote " + b.position() + " bytes instead of " + size);
        }
        return b.array();
    }

    static int u8(ByteBuffer b) {
        return b.get() & 0xFF;
    }

    static int u16(ByteBuffer b) {
        return b.getShort() & 0xFFFF;
    }
}
