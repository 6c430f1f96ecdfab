package touchline.protocol.gamecontroller;

import java.util.List;

/**
 * Recognises a game-state datagram heard on the network in any format we know, keyed on
 * magic, version and exact length (never guessed from one field alone). Used to watch other
 * GameControllers; what we send is always the one explicitly configured format.
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

    private final List<GameStateFormat> formats = List.of(new HlGameState12(), HlGameState12.legacy640(),
            new SplGameState18(), new GameState8(), new GameState7());

    /** Whether the datagram starts with the game-state magic "RGme". */
    public static boolean isGameState(byte[] data) {
        return data != null && data.length >= 4 && data[0] == 'R' && data[1] == 'G' && data[2] == 'm'
                && data[3] == 'e';
    }

    /** The matching format and content, or null when no known format accepts the bytes. */
    public Match decode(byte[] datagram) {
        for (GameStateFormat f : formats) {
            Decoded<GameControlData> d = f.decode(datagram);
            if (d.isOk()) {
                return new Match(f, d.value());
            }
        }
        return null;
    }
}
