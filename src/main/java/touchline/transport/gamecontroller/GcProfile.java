package touchline.transport.gamecontroller;

import touchline.protocol.gamecontroller.GameState7;
import touchline.protocol.gamecontroller.GameState8;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.SplGameState18;

import java.util.Locale;
import java.util.function.Supplier;

/**
 * The explicit GameController setting: which game-state format is sent and where return
 * packets arrive. The format is never guessed from the network. Since 2016 robots answer on
 * 3939; the 2014-era profiles (v8, v7) get return packets on 3838, next to our own broadcasts.
 */
public enum GcProfile {
    HL12("hl12", HlGameState12::new, 3939),
    /** HL v12 in its 640-byte layout of 2017-06 … 2021-04 (same version number). */
    HL12_640("hl12-640", HlGameState12::legacy640, 3939),
    SPL18("spl18", SplGameState18::new, 3939),
    V8("v8", GameState8::new, 3838),
    V7("v7", GameState7::new, 3838);

    public static final int GAME_STATE_PORT = 3838;

    private final String cliName;
    private final Supplier<GameStateFormat> format;
    private final int returnPort;

    GcProfile(String cliName, Supplier<GameStateFormat> format, int returnPort) {
        this.cliName = cliName;
        this.format = format;
        this.returnPort = returnPort;
    }

    public String cliName() {
        return cliName;
    }

    public GameStateFormat format() {
        return format.get();
    }

    public int defaultReturnPort() {
        return returnPort;
    }

    /** Whether return packets share the game-state port (so our own packets must be ignored there). */
    public boolean returnsOnGameStatePort() {
        return returnPort == GAME_STATE_PORT;
    }

    /** Parses {@code hl12|spl18|v8|v7}; null when unknown. */
    public static GcProfile parse(String name) {
        for (GcProfile p : values()) {
            if (p.cliName.equals(name.toLowerCase(Locale.ROOT))) {
                return p;
            }
        }
        return null;
    }
}
