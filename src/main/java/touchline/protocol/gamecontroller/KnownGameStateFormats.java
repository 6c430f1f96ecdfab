package touchline.protocol.gamecontroller;

import java.util.List;

/**
 * Recognises a game-state datagram heard on the network in any format we know, keyed on
 * magic, version and exact length (never guessed from one field alone: 158 bytes is both the
 * 2014 v8 and the 2026 HSL v20, and the version byte decides). Used to watch other
 * GameControllers; what we send is always the one explicitly configured format. A datagram no
 * format accepts gets the reason of the format whose header and version it carries (wrong
 * length, a value out of range), or "unknown version".
 */
public final class KnownGameStateFormats {

    /**
     * A recognised datagram.
     *
     * @param format the format it matched
     * @param data   its content
     */
    public record Match(GameStateFormat format, GameControlData data) {
    }

    private final List<FixedSizeFormat> formats = List.of(new HslGameState20(), HslGameState20.trueData(),
            new HslGameState19(), HslGameState19.trueData(), new HlGameState12(), HlGameState12.legacy640(),
            new SplGameState18(), new GameState8(), new GameState7());

    /** Whether the datagram starts with a game-state magic: "RGme", or the monitors' "RGTD". */
    public static boolean isGameState(byte[] data) {
        return data != null && data.length >= 4 && data[0] == 'R' && data[1] == 'G'
                && (data[2] == 'm' && data[3] == 'e' || data[2] == 'T' && data[3] == 'D');
    }

    /** The matching format and content, or null when no known format accepts the bytes. */
    public Match decode(byte[] datagram) {
        Decoded<Match> d = recognise(datagram);
        return d.isOk() ? d.value() : null;
    }

    /** The matching format and content, or why no known format accepts the bytes. */
    public Decoded<Match> recognise(byte[] datagram) {
        Decoded<Match> reason = null;
        for (FixedSizeFormat f : formats) {
            Decoded<GameControlData> d = f.decode(datagram);
            if (d.isOk()) {
                return Decoded.ok(new Match(f, d.value()));
            }
            if (reason == null && f.claims(datagram)) {
                reason = Decoded.rejected(d.failure(), f.kind() + " (version " + f.version() + ", " + f.size()
                        + " bytes): " + d.detail());
            }
        }
        if (reason != null) {
            return reason;
        }
        if (!isGameState(datagram)) {
            return Decoded.rejected(DecodeFailure.WRONG_MAGIC, "not a game-state packet (header RGme or RGTD)");
        }
        return Decoded.rejected(DecodeFailure.WRONG_VERSION, "game-state packet of " + datagram.length
                + " bytes with version byte " + (datagram.length > 4 ? datagram[4] & 0xFF : -1) + ": no known format");
    }
}
