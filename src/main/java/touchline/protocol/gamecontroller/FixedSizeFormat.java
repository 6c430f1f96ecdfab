package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;

/**
 * What every game-state format shares: envelope kind, version and exact size, and the frame
 * "RGme" (or the HSL monitors' "RGTD") + version field, whose width changed over the years (u32 in v7, u8 in v8 and SPL,
 * u16 in HL v12). Encoding and decoding check the frame here; subclasses supply only the
 * layout after the version field.
 */
abstract class FixedSizeFormat implements GameStateFormat {

    private final String kind;
    private final byte[] magic;
    private final int version;
    private final int versionWidth;
    private final int size;

    FixedSizeFormat(String kind, int version, int versionWidth, int size) {
        this(kind, WireChecks.GAME_STATE_MAGIC, version, versionWidth, size);
    }

    FixedSizeFormat(String kind, byte[] magic, int version, int versionWidth, int size) {
        this.kind = kind;
        this.magic = magic;
        this.version = version;
        this.versionWidth = versionWidth;
        this.size = size;
    }

    @Override
    public final boolean isTrueData() {
        return magic == WireChecks.TRUE_DATA_MAGIC;
    }

    /**
     * Whether the datagram carries this format's header and version number, whatever its length:
     * then this format's verdict (right length? valid fields?) is the one that explains it.
     */
    final boolean claims(byte[] datagram) {
        if (datagram == null || datagram.length < 4 + versionWidth) {
            return false;
        }
        for (int i = 0; i < 4; i++) {
            if (datagram[i] != magic[i]) {
                return false;
            }
        }
        return readVersion(WireChecks.reader(datagram).position(4)) == version;
    }

    private long readVersion(ByteBuffer b) {
        return switch (versionWidth) {
            case 1 -> WireChecks.u8(b);
            case 2 -> WireChecks.u16(b);
            default -> b.getInt() & 0xFFFFFFFFL;
        };
    }

    @Override
    public final String kind() {
        return kind;
    }

    @Override
    public final int version() {
        return version;
    }

    @Override
    public final int size() {
        return size;
    }

    @Override
    public final byte[] encode(GameControlData data) {
        ByteBuffer b = WireChecks.writer(size);
        b.put(magic);
        switch (versionWidth) {
            case 1 -> b.put((byte) version);
            case 2 -> b.putShort((short) version);
            default -> b.putInt(version);
        }
        encodeBody(data, b);
        return WireChecks.finish(b, size);
    }

    @Override
    public final Decoded<GameControlData> decode(byte[] datagram) {
        Decoded<GameControlData> bad = WireChecks.checkFrame(datagram, size, magic);
        if (bad != null) {
            return bad;
        }
        ByteBuffer b = WireChecks.reader(datagram);
        b.position(4);
        long got = readVersion(b);
        if (got != version) {
            return WireChecks.wrongVersion(version, got);
        }
        return decodeBody(b);
    }

    /** Writes everything after the version field. */
    abstract void encodeBody(GameControlData d, ByteBuffer b);

    /** Reads everything after the version field (the frame is already checked). */
    abstract Decoded<GameControlData> decodeBody(ByteBuffer b);
}
