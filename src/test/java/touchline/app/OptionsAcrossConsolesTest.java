package touchline.app;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.proto.Fumanoid;
import touchline.testing.Await;
import touchline.testing.LoopbackField;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue #14: the debug options belong to the user, not to one console. Two consoles of one
 * team and one real simulated robot on loopback (the field's broadcast played by
 * {@link LoopbackField}): a console starting later does not switch off what the other wants,
 * switching off one's own option leaves the other's on, and a restarted console wants again
 * what it wanted before.
 */
@Tag("integration")
class OptionsAcrossConsolesTest {

    private static final int ROBOT = 7;

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }

    private static boolean streaming(Console c, String option) {
        return c.field().options().options(ROBOT).option(option).map(o -> o.streaming()).orElse(false);
    }

    private static long offRequests(List<Envelope> out, String option) {
        return out.stream().filter(e -> e.direction() == Direction.OUT && e.message() instanceof Fumanoid.Message m
                && m.hasExtension(Fumanoid.debugOptionRequest)
                && m.getExtension(Fumanoid.debugOptionRequest).getName().equals(option)
                && !m.getExtension(Fumanoid.debugOptionRequest).getEnable()).count();
    }

    @Test
    void twoConsolesOfOneTeamKeepEachOthersOptionsAndARestartWantsThemAgain(@TempDir Path dirA, @TempDir Path dirB)
            throws Exception {
        Path fileA = dirA.resolve("wanted-options.properties");
        try (LoopbackField field = new LoopbackField()) {
            try (Console a = field.join()) {
            a.optionSwitches().rememberWanted(fileA);
            try (RobotProcess robot = RobotProcess.robot(ROBOT, field.port()).start()) {
                field.robotAt(robot.port());
                Await.until("console A has the option list", () -> a.field().options().options(ROBOT).listReceived());
                assertTrue(a.optionSwitches().set(ROBOT, "demo.text", true).isSent());
                Await.until("demo.text streams to A", () -> streaming(a, "demo.text"));

                List<Envelope> fromB = new CopyOnWriteArrayList<>();
                try (Console b = field.join()) {
                    b.optionSwitches().rememberWanted(dirB.resolve("wanted-options.properties"));
                    b.field().bus().subscribe(fromB::add);
                    Await.until("console B has the option list", () -> b.field().options().options(ROBOT).listReceived());
                    assertTrue(b.optionSwitches().set(ROBOT, "demo.plotter", true).isSent());
                    Await.until("demo.plotter streams to B", () -> streaming(b, "demo.plotter"));
                    Await.until("B sees A's demo.text streaming too", () -> streaming(b, "demo.text"));
                    // B's reconciliation has run many times by now (every 100 ms)
                    long ticksSeen = fromB.size();
                    Await.until("B keeps hearing the robot", () -> fromB.size() > ticksSeen + 20);
                    assertEquals(0, offRequests(fromB, "demo.text"), "B never switched off A's option");
                    assertTrue(streaming(a, "demo.text"), "A's option is still on");

                    assertTrue(b.optionSwitches().set(ROBOT, "demo.plotter", false).isSent());
                    Await.until("demo.plotter stops for A", () -> !streaming(a, "demo.plotter"));
                    assertTrue(streaming(a, "demo.text"), "B switching its option off left A's on");
                    assertFalse(b.optionSwitches().set(ROBOT, "demo.text", false).isSent(), "B may not switch off A's option");
                    field.forget(b.field().port());
                }
                assertTrue(streaming(a, "demo.text"), "closing B switched nothing off");

                // A and the robot stop; the robot starts afresh, so nothing is on when A comes back
                field.forget(a.field().port());
            }
            }
            try (RobotProcess robot = RobotProcess.robot(ROBOT, field.port()).start();
                 Console again = field.join()) {
                field.robotAt(robot.port());
                again.optionSwitches().rememberWanted(fileA);
                assertEquals(Set.of("demo.text"), again.field().options().wanted(ROBOT), "restored before the robot is seen");
                Await.until("demo.text streams again to the restarted A without a click", () -> streaming(again, "demo.text"));
            }
        }
    }
}
