package touchline.fuzz;

import touchline.protocol.gamecontroller.GameState7;
import touchline.protocol.gamecontroller.GameState8;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.SplGameState18;

import java.util.ArrayList;
import java.util.List;

/**
 * A game-state datagram heard on the network, recognised in every format the console knows
 * (whatever {@link KnownGameStateFormats} lists); a recognised one encodes again to its format's
 * exact size.
 */
final class GameStateTarget implements FuzzTarget {

    private final KnownGameStateFormats formats = new KnownGameStateFormats();

    @Override
    public String name() {
        return "gamecontroller";
    }

    @Override
    public void accept(byte[] input) {
        KnownGameStateFormats.isGameState(input);
        KnownGameStateFormats.Match match = formats.decode(input);
        if (match != null) {
            byte[] again = match.format().encode(match.data());
            FuzzTarget.check(again.length == match.format().size(), match.format().kind() + " encoded to "
                    + again.length + " bytes");
        }
    }

    /** The golden HL 12 packets, and each of them in every other format we can write. */
    @Override
    public List<byte[]> seeds() {
        List<byte[]> golden = new Samples().golden("gamecontroller");
        List<GameStateFormat> writers = List.of(new HlGameState12(), HlGameState12.legacy640(), new SplGameState18(),
                new GameState8(), new GameState7());
        List<byte[]> seeds = new ArrayList<>(golden);
        for (byte[] g : golden) {
            KnownGameStateFormats.Match m = formats.decode(g);
            if (m == null) {
                continue;
            }
            for (GameStateFormat f : writers) {
                try {
                    seeds.add(f.encode(m.data()));
                } catch (RuntimeException notRepresentable) {
                    // some content has no encoding in an older format; its other seeds stand in
                }
            }
        }
        return seeds;
    }
}
