package touchline.game.hsl;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import touchline.game.ManualClock;
import touchline.game.Outcome;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.HslGameState19;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.TeamColour;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * Plays the script of the official golden games (HSL GameController 7.0.0-rc.3 for version 20,
 * 6.0.1 for version 19; golden/gamecontroller/hsl20|hsl19/README.md) through our game logic on
 * a manual clock and compares what robots get with every step file, and the monitors' true
 * data with every {@code .monitor.bin}, byte for byte (packetNumber from the file: the stream
 * test checks the numbering). A difference names the step, the byte offset and the field.
 */
public class HslGameGoldenTest {

    static final TeamColour[] HOME = {TeamColour.RED, TeamColour.PURPLE};
    static final TeamColour[] AWAY = {TeamColour.BLUE, TeamColour.YELLOW};

    public static HslGame goldenGame(int version, ManualClock clock) {
        HslRules rules = HslRules.forVersion(version, Competition.MIDDLE_ADVANCED);
        return new HslGame(rules, 5, HOME, 14, AWAY, clock);
    }

    public static void perform(HslGame game, String command, String where) {
        HslActionSyntax.Parsed parsed = new HslActionSyntax().parse(command);
        assertTrue(parsed.error() == null, where + ": '" + command + "': " + parsed.error());
        Outcome o = game.perform(parsed.action());
        assertTrue(o.applied(), where + ": '" + command + "' refused: " + o.message());
    }

    @ParameterizedTest(name = "version {0}")
    @ValueSource(ints = {20, 19})
    void everyStepFileIsReproducedByteForByte(int version) throws IOException {
        ManualClock clock = new ManualClock(0);
        HslGame game = goldenGame(version, clock);
        GameStateFormat robots = version == 20 ? new HslGameState20() : new HslGameState19();
        GameStateFormat monitors = version == 20 ? HslGameState20.trueData() : HslGameState19.trueData();
        List<String> differences = new ArrayList<>();
        int compared = 0;
        for (HslGoldenScript.Step step : HslGoldenScript.of(version)) {
            clock.set(step.atMs());
            game.advance();
            for (String command : step.commands()) {
                perform(game, command, step.file() == null ? "at " + step.atMs() + " ms" : step.file());
            }
            if (step.file() == null) {
                continue;
            }
            clock.set(step.sentAtMs());
            byte[] expected = golden(version, step.file());
            int packetNumber = expected[5] & 0xFF;
            compared++;
            compare(step.file(), expected, robots.encode(game.controlData().withPacketNumber(packetNumber)), version,
                    differences);
            byte[] monitor = goldenOrNull(version, step.file().replace(".bin", ".monitor.bin"));
            if (monitor != null) {
                compare(step.file().replace(".bin", ".monitor.bin"), monitor,
                        monitors.encode(game.trueData().withPacketNumber(packetNumber)), version, differences);
            }
        }
        assertEquals(version == 20 ? 54 : 52, compared, "step files compared");
        if (!differences.isEmpty()) {
            fail(differences.size() + " golden file(s) differ:\n" + String.join("\n", differences));
        }
    }

    public static void compare(String file, byte[] expected, byte[] actual, int version, List<String> out) {
        if (java.util.Arrays.equals(expected, actual)) {
            return;
        }
        StringBuilder b = new StringBuilder(file + ":");
        for (int i = 0; i < Math.min(expected.length, actual.length); i++) {
            if (expected[i] != actual[i]) {
                b.append(String.format(" byte %d (%s) expected %d got %d;", i, HslFields.name(i, version),
                        expected[i] & 0xFF, actual[i] & 0xFF));
            }
        }
        if (expected.length != actual.length) {
            b.append(" length ").append(expected.length).append(" vs ").append(actual.length);
        }
        out.add(b.toString());
    }

    public static byte[] golden(int version, String file) throws IOException {
        byte[] b = goldenOrNull(version, file);
        assertNotNull(b, "missing golden file hsl" + version + "/" + file);
        return b;
    }

    static byte[] goldenOrNull(int version, String file) throws IOException {
        try (InputStream in = HslGameGoldenTest.class.getResourceAsStream(
                "/golden/gamecontroller/hsl" + version + "/" + file)) {
            return in == null ? null : in.readAllBytes();
        }
    }

    static String hex(byte[] b) {
        return HexFormat.of().formatHex(b);
    }

    /** Decoded for failure messages: the whole data as text. */
    static String describe(GameControlData d) {
        return d.toString();
    }
}
