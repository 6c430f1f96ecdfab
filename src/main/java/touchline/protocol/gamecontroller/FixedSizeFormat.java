package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;

/**
 * What every game-state format shares: envelope kind, version and exact size, and the frame
 * "RGme" + version field, whose width changed over the years (u32 in v7, u8 in v8 and SPL,
 * u16 in HL v12). Encoding and decoding check the frame here; subclasses supply only the
 * layout after the version field.
 */
abstract class FixedSizeFormat implements GameStateFormat {

    private final String kind;
    private final int version;
    private final int versionWidth;
    private final int size;

    FixedSizeFormat(String kind, int version, int versionWidth, int size) {
        this.kind = kind;
        this.version = version;
        this.versionWidth = versionWidth;
        this.size = size;
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
        b.put(WireChecks.GAME_STATE_MAGIC);
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
        Decoded<GameControlData> bad = WireChecks.checkFrame(datagram, size, WireChecks.GAME_STATE_MAGIC);
        if (bad != null) {
            return bad;
        }
        ByteBuffer b = WireChecks.reader(datagram);
        b.position(4);
        long got = switch (versionWidth) {
            case 1 -> WireChecks.u8(b);
            case 2 -> WireChecks.u16(b);
            default -> b.getInt() & 0xFFFFFFFFL;
        };
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
