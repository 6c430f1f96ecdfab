package touchline.transport.gamecontroller;

import touchline.protocol.gamecontroller.GameState7;
import touchline.protocol.gamecontroller.GameState8;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.HslGameState19;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.SplGameState18;

import java.util.Locale;
import java.util.function.Supplier;

/**
 * The explicit GameController setting: which game-state format is sent and where return
 * packets arrive. The format is never guessed from the network. Since 2016 robots answer on
 * 3939; the 2014-era profiles (v8, v7) get return packets on 3838, next to our own broadcasts.
 */
public enum GcProfile {
    /** HSL v20, 158 bytes: the official GameController 7.x (RoboCup 2026); the 2026 rules. */
    HSL20("hsl20", HslGameState20::new, 3939),
    /** HSL v19, 198 bytes: GameController 6.0.x (German Open 2026). */
    HSL19("hsl19", HslGameState19::new, 3939),
    HL12("hl12", HlGameState12::new, 3939),
    /** HL v12 in its 640-byte layout of 2017-06 … 2021-04 (same version number). */
    HL12_640("hl12-640", HlGameState12::legacy640, 3939),
    SPL18("spl18", SplGameState18::new, 3939),
    V8("v8", GameState8::new, 3838),
    V7("v7", GameState7::new, 3838);

    public static final int GAME_STATE_PORT = 3838;

    /** The format of the CLI when none is given: the field's format since 2026. */
    public static final GcProfile DEFAULT = HSL20;

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

    /**
     * Whether this is a Humanoid Soccer League (2026) format: its games follow the HSL rules
     * ({@code touchline.game.hsl}) and it is sent on the official HSL schedule (a burst when play
     * gets stopped instead of a datagram after every change).
     */
    public boolean hsl() {
        return this == HSL20 || this == HSL19;
    }

    /** The monitors' true-data ("RGTD") format of an HSL format; null for the others. */
    public GameStateFormat trueDataFormat() {
        return this == HSL20 ? HslGameState20.trueData() : this == HSL19 ? HslGameState19.trueData() : null;
    }

    /** The protocol version of an HSL format (20 or 19); 0 for the others. */
    public int hslVersion() {
        return this == HSL20 ? HslGameState20.VERSION : this == HSL19 ? HslGameState19.VERSION : 0;
    }

    /** Whether return packets share the game-state port (so our own packets must be ignored there). */
    public boolean returnsOnGameStatePort() {
        return returnPort == GAME_STATE_PORT;
    }

    /** All CLI names, e.g. for error messages: {@code hsl20, hsl19, hl12, ...}. */
    public static String names() {
        StringBuilder b = new StringBuilder();
        for (GcProfile p : values()) {
            b.append(b.length() == 0 ? "" : ", ").append(p.cliName);
        }
        return b.toString();
    }

    /** Parses {@code hsl20|hsl19|hl12|hl12-640|spl18|v8|v7}; null when unknown. */
    public static GcProfile parse(String name) {
        for (GcProfile p : values()) {
            if (p.cliName.equals(name.toLowerCase(Locale.ROOT))) {
                return p;
            }
        }
        return null;
    }
}
