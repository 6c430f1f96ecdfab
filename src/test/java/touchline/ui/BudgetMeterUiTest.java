package touchline.ui;

import javafx.scene.control.Label;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.RuleProfile;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The status bar's meter shows the active profile's limit: with the budget guard on, the team's
 * messages against the HSL 2026 budget, and an oversized message at once with its sender.
 * Team messages are real datagrams on loopback.
 */
@Tag("ui")
class BudgetMeterUiTest {

    @TempDir
    Path layouts;
    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui = new ConsoleWindowFixture(layouts);
    }

    @AfterEach
    void close() throws Exception {
        ui.close();
    }

    private String meter() throws Exception {
        return ui.fx(() -> ((Label) ui.window.status().lookup("#status-meter")).getText());
    }

    @Test
    void theMeterCountsTheTeamsMessagesAndFlagsAnOversizedOne() throws Exception {
        ui.console.guardTeamMessages(RuleProfile.named("hsl-2026"), 13, new InetSocketAddress("127.0.0.1", 0));
        int port = ui.console.teamMessagePort();
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            InetSocketAddress to = new InetSocketAddress("127.0.0.1", port);
            for (int i = 0; i < 3; i++) {
                robot.send(new DatagramPacket(new byte[40], 40, to));
            }
            ui.await(30, () -> meter().contains("team 13 messages: 3 used") && meter().contains("11997 left"));
            robot.send(new DatagramPacket(new byte[600], 600, to));
            ui.await(30, () -> meter().contains("over 512 bytes"));
            String m = meter();
            assertTrue(m.contains("127.0.0.1:" + robot.getLocalPort()) && m.contains("600 bytes"), m);
        }
    }
}
