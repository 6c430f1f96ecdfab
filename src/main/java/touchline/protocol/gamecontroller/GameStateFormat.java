package touchline.protocol.gamecontroller;

/**
 * One wire format of the game-state ("RGme") packet: a fixed size, a version and a pure
 * encoder/decoder pair. One implementation per version, because the same version number has
 * meant different layouts over the years; the format in use is always an explicit setting.
 */
public interface GameStateFormat {

    /** Envelope kind of packets in this format, e.g. {@code gc.hl12}. */
    String kind();

    /** The version number written into the packet. */
    int version();

    /** Exact datagram size in bytes. */
    int size();

    /** Encodes {@code data}; the result is always exactly {@link #size()} bytes. */
    byte[] encode(GameControlData data);

    /**
     * Whether this is the HSL "true data" copy ("RGTD") a GameController sends to registered
     * monitors: the real state, without the 10 s of SET robots see after a whistle.
     */
    default boolean isTrueData() {
        return false;
    }

    /** Decodes a datagram; wrong length, magic or version are rejected, never thrown. */
    Decoded<GameControlData> decode(byte[] datagram);
}
