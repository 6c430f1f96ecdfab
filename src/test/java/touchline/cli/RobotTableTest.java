package touchline.cli;

import org.junit.jupiter.api.Test;
import touchline.model.MatchDebugRule;
import touchline.model.RobotAuth;
import touchline.model.RobotSnapshot;
import touchline.transport.Origin;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code listen}'s robot table says when a robot heard a GameController it did not believe. */
class RobotTableTest {

    private static RobotSnapshot robot(int id, long gcOtherSource) {
        return new RobotSnapshot(id, "robot " + id, 13, 80, "striker", "playing", "PLAYING", 0, 0, 0, false, 10, 0, 0,
                true, 1, 1, 1, 0, 0, null, Origin.LIVE, RobotAuth.NONE, gcOtherSource);
    }

    @Test
    void aRobotThatHeardAnotherGameControllerGetsALine() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        new RobotTable(id -> new MatchDebugRule.Reading(id, false, 0, 0, 0, List.of()))
                .print(new PrintStream(bytes, true, StandardCharsets.UTF_8), List.of(robot(3, 0), robot(8, 1234)),
                        List.of(), List.of());
        String text = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(text.contains("  robot 8: 1234 GameController packet(s) from another source than the one it follows,"
                + " not believed"), text);
        assertFalse(text.contains("robot 3: "), text);
    }

    @Test
    void aRobotInPlayGetsTheDebugRulesReadingAndABreachIsSaid() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        new RobotTable(id -> id == 8
                ? new MatchDebugRule.Reading(8, true, 2.0, 412, 1, List.of("too often: 2.0 datagrams per period"))
                : new MatchDebugRule.Reading(id, true, 1.0, 300, 1, List.of()))
                .print(new PrintStream(bytes, true, StandardCharsets.UTF_8), List.of(robot(3, 0), robot(8, 0)),
                        List.of(), List.of());
        String text = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(text.contains("  robot 3 in play: 1.0/period, biggest 300 B (1 fragment)\n")
                || text.contains("  robot 3 in play: 1.0/period, biggest 300 B (1 fragment)" + System.lineSeparator()), text);
        assertTrue(text.contains("  robot 8 in play: 2.0/period, biggest 412 B (1 fragment): too often: 2.0 datagrams"
                + " per period — BREAKS THE DEBUG RULE"), text);
    }
}
