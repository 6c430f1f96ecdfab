package touchline.ui.referee;

import javafx.scene.control.TextArea;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.protocol.gamecontroller.ReturnPacket;
import touchline.testing.UiTest;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ConsoleWindowFixture;

/**
 * The window registered as a monitor with a (loopback) HSL GameController shows each robot as
 * the GameController sees it: the forwarded return packet's fallen flag, pose and ball.
 */
@UiTest
class GcRobotsViewUiTest {

    @TempDir
    Path layouts;

    @Test
    void aForwardedReturnPacketShowsTheRobotAsTheGameControllerSeesIt() throws Exception {
        try (DatagramSocket gameController = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
             ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts, ConsoleWindowFixture.loopback().withGcMonitor(
                     new InetSocketAddress(InetAddress.getLoopbackAddress(), gameController.getLocalPort()), 0))) {
            ui.fxRun(() -> ui.window.open("gc-robots", ViewSource.NONE));
            InetSocketAddress forward = ui.console.referee().monitor().forwardAddress();
            byte[] packet = new ForwardedReturnPacket(new byte[]{10, 0, 5, 12},
                    new ReturnPacket.V4(3, 5, 1, 1500f, -200f, 0.5f, 2.0f, 300f, 40f)).encode();
            gameController.send(new DatagramPacket(packet, packet.length, forward));
            ui.await(30, () -> ui.robot.lookup("#gc-robots-text").queryAs(TextArea.class).getText().contains("FALLEN"));
            String text = ui.fx(() -> ui.robot.lookup("#gc-robots-text").queryAs(TextArea.class).getText());
            assertTrue(text.contains("10.0.5.12") && text.contains("pose (1500, -200, 0.50)") && text.contains("(300, 40)"),
                    text);
        }
    }
}
