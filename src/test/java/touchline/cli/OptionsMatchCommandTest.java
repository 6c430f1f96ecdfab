package touchline.cli;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.model.OptionState;
import touchline.testing.Await;
import touchline.testing.LoopbackField;
import touchline.testing.RobotProcess;

import java.io.StringWriter;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * {@code options ROBOT --match NAME…} chooses the robot's match items outside play; the command
 * ends once the real simulated robot's option list confirms each place, and another console
 * sees the robot's choice in that list.
 */
@Tag("integration")
class OptionsMatchCommandTest {

    private static int rank(Console c, String option) {
        return c.field().options().options(8).option(option).map(OptionState::matchRankOnRobot).orElse(-1);
    }

    @Test
    void matchChoosesTheRobotsDigestItemsInOrder() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (LoopbackField field = new LoopbackField(); Console watcher = field.join();
             RobotProcess robot = RobotProcess.robot(8, field.port()).start()) {
            field.robotAt(robot.port());
            Await.until("the watcher has the list", () -> watcher.field().options().options(8).listReceived());
            int port;
            try (DatagramSocket free = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
                port = free.getLocalPort();
            }
            field.console(port);
            StringWriter err = new StringWriter();
            int code = Main.execute(new String[] {"options", "8", "--match", "demo.field", "--match", "demo.plotter",
                    "--bind", "127.0.0.1", "--port", Integer.toString(port), "--timeout", "10"},
                    new java.io.PrintWriter(err));
            assertEquals(0, code, err.toString());
            Await.until("the robot's list shows the places", () -> rank(watcher, "demo.field") == 1
                    && rank(watcher, "demo.plotter") == 2);
            assertEquals(0, rank(watcher, "demo.text"));

            code = Main.execute(new String[] {"options", "8", "--match", "demo.nothing", "--bind", "127.0.0.1",
                    "--port", Integer.toString(port), "--timeout", "10"}, new java.io.PrintWriter(err));
            assertEquals(1, code, err.toString());
            assertEquals(true, err.toString().contains("robot 8 offers no option 'demo.nothing'"), err.toString());
        }
    }
}
