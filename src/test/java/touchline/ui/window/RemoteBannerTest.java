package touchline.ui.window;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.testing.Await;
import touchline.transport.UdpConfig;

import java.net.ServerSocket;
import java.net.URI;

import static org.junit.jupiter.api.Assertions.*;
import touchline.ui.frame.ConsoleStatus;

/**
 * A window viewing another Touchline says so in the status bar's banner, with the connection's
 * state and that commands are off: here a server that is not there, so "lost, reconnecting".
 */
@Tag("integration")
class RemoteBannerTest {

    @Test
    void theBannerSaysWhatIsViewedThatTheConnectionIsLostAndThatCommandsAreOff() throws Exception {
        int nobody;
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            nobody = s.getLocalPort(); // free again once closed: nothing listens there
        }
        try (Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start()) {
            ConsoleStatus status = new ConsoleStatus(console.field(), console.referee(), console.replays(), console.remote());
            assertFalse(status.silence().contains(Console.COMMANDS_OFF), "a console on the field sends");
            console.remote().view(new URI("ws://127.0.0.1:" + nobody + "/?token=secret"), null);
            Await.until("lost", () -> status.silence().contains("lost"));
            String banner = status.silence();
            assertTrue(banner.startsWith("connection to ws://127.0.0.1:" + nobody + "/ lost (nobody listening), reconnecting…"),
                    banner);
            assertTrue(banner.endsWith(Console.COMMANDS_OFF), banner);
            assertFalse(banner.contains("secret"), "the token is not shown: " + banner);
        }
    }
}
