package touchline.cli;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.testing.Await;
import touchline.testing.LoopbackField;
import touchline.testing.RobotProcess;

import java.io.StringWriter;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.*;

/**
 * {@code options ROBOT --off NAME} names the option, so it goes off even though that one-shot
 * console never switched it on (another console did), against the real simulated robot.
 */
@Tag("integration")
class OptionsOffCommandTest {

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }

    private static boolean streaming(Console c) {
        return c.field().options().options(8).option("demo.text").map(o -> o.streaming()).orElse(false);
    }

    @Test
    void offSwitchesOffAnOptionAnotherConsoleSwitchedOn() throws Exception {
        try (LoopbackField field = new LoopbackField(); Console watcher = field.join()) {
            try (RobotProcess robot = RobotProcess.robot(8, field.port()).start()) {
                field.robotAt(robot.port());
                try (Console other = field.join()) {
                    Await.until("the other console has the list", () -> other.field().options().options(8).listReceived());
                    assertTrue(other.optionSwitches().set(8, "demo.text", true).isSent());
                    Await.until("demo.text streams", () -> streaming(watcher));
                    field.forget(other.field().port());
                }
                int port;
                try (DatagramSocket free = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
                    port = free.getLocalPort();
                }
                field.console(port);
                StringWriter err = new StringWriter();
                int code = Main.execute(new String[] {"options", "8", "--off", "demo.text", "--bind", "127.0.0.1",
                        "--port", Integer.toString(port), "--timeout", "10"}, new java.io.PrintWriter(err));
                assertEquals(0, code, err.toString());
                Await.until("demo.text stops", () -> !streaming(watcher));
            }
        }
    }
}
