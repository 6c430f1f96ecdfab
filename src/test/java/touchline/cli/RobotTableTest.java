package touchline.cli;

import org.junit.jupiter.api.Test;
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
        new RobotTable().print(new PrintStream(bytes, true, StandardCharsets.UTF_8), List.of(robot(3, 0), robot(8, 1234)),
                List.of(), List.of());
        String text = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(text.contains("  robot 8: 1234 GameController packet(s) from another source than the one it follows,"
                + " not believed"), text);
        assertFalse(text.contains("robot 3: "), text);
    }
}
