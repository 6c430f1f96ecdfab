package touchline.ui.window;

import javafx.scene.control.Label;
import javafx.scene.text.Text;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.model.RuleProfile;
import touchline.testing.UiTest;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.referee.GameControllerTabDriver;

/**
 * The status bar's meter shows the active profile's limit: with the budget guard on, the team's
 * messages against the HSL 2026 budget, counted as the GameController counts them, in a place that
 * reads whole in a 1280-pixel window in play, and an oversized message at once.
 * Team messages are real datagrams on loopback; the GameController is the console's own.
 */
@UiTest
class BudgetMeterUiTest {

    private ConsoleWindowFixture ui;
    private DatagramSocket field;

    @BeforeEach
    void open() throws Exception {
        field = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        ui.laptopSize();
    }

    @AfterEach
    void close() throws Exception {
        ui.console.referee().stop();
        field.close();
    }

    private Label meter() throws Exception {
        return ui.fx(() -> (Label) ui.window.status().lookup("#status-meter"));
    }

    private String text() throws Exception {
        return ui.fx(() -> meter().getText());
    }

    /** What the label draws: its text, or the text cut to "…" when it has less room than it needs. */
    private String shown() throws Exception {
        return ui.fx(() -> ((Text) meter().lookup(".text")).getText());
    }

    @Test
    void theMeterCountsByTheRulesAndReadsWholeInPlayAtA1280PixelWindow() throws Exception {
        ui.console.teamBudget().guard(RuleProfile.named("hsl-2026"), 13, new InetSocketAddress("127.0.0.1", 0));
        int port = ui.console.teamBudget().port();
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            InetSocketAddress to = new InetSocketAddress("127.0.0.1", port);
            for (int i = 0; i < 3; i++) {
                robot.send(new DatagramPacket(new byte[40], 40, to));
            }
            // no GameController heard: the state is not known, INITIAL does not count
            ui.await(30, () -> ui.fx(() -> meter().getTooltip().getText()).contains("3 heard, not counted"));
            assertEquals("team 13: 0 used · 12000 left · no GameController: not counting", text());

            GameControllerTabDriver gc = new GameControllerTabDriver(ui);
            gc.start(field, "hsl20"); // teams 13 and 7, INITIAL
            robot.send(new DatagramPacket(new byte[40], 40, to));
            ui.await(30, () -> ui.console.teamBudget().budget().orElseThrow().snapshot().notCounted() == 4
                    || text().contains("1 used"));
            assertTrue(text().startsWith("team 13: 0 used"), "INITIAL does not count: " + text());
            gc.press("#gc-ready");
            ui.await(30, () -> ui.console.referee().matchMode().playIsOn());
            for (int i = 0; i < 3; i++) {
                robot.send(new DatagramPacket(new byte[40], 40, to));
            }
            ui.await(30, () -> text().startsWith("team 13: 3 used · "));
            // in play, with the match-mode banner beside it, the meter reads whole and its tooltip
            // covers all of it: one label, the bar its graphic
            ui.await(30, () -> !ui.fx(() -> ui.window.status().lookup("#status-silence").isVisible()) ? false
                    : shown().equals(text()));
            assertTrue(ui.fx(() -> meter().getWidth() + 0.5 >= meter().prefWidth(-1)), "the meter never gives way");
            // nor the frame rate (ViewsFitUiTest saw it cut under load, when its p99 appeared), and the bar
            // as a whole stays inside the window
            ui.await(30, () -> ui.fx(() -> {
                Label fps = (Label) ui.window.status().lookup("#status-fps");
                return !fps.getText().isEmpty() && fps.getWidth() + 0.5 >= fps.prefWidth(-1)
                        && fps.localToScene(fps.getLayoutBounds()).getMaxX() <= ui.window.scene().getWidth() + 0.5;
            }));
            String tip = ui.fx(() -> meter().getTooltip().getText());
            assertTrue(tip.contains("READY, SET and PLAYING only") && tip.contains("127.0.0.1:" + robot.getLocalPort()), tip);

            robot.send(new DatagramPacket(new byte[600], 600, to));
            ui.await(30, () -> text().contains("1 OVERSIZE"));
            ui.await(30, () -> shown().equals(text()));
            String details = ui.fx(() -> meter().getTooltip().getText());
            assertTrue(details.contains("127.0.0.1:" + robot.getLocalPort()) && details.contains("600 bytes"), details);
        }
    }

    /** The status bar's "in" rate counts the team messages the console hears (it read 0 pkt/s while they came). */
    @Test
    void theInRateCountsTeamMessages() throws Exception {
        ui.console.teamBudget().guard(RuleProfile.named("hsl-2026"), 13, new InetSocketAddress("127.0.0.1", 0));
        InetSocketAddress to = new InetSocketAddress("127.0.0.1", ui.console.teamBudget().port());
        java.util.regex.Pattern in = java.util.regex.Pattern.compile("^in (\\d+) pkt/s");
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            // no robot talks to the console: only team messages arrive, a few on every look
            ui.await(30, () -> {
                for (int i = 0; i < 5; i++) {
                    robot.send(new DatagramPacket(new byte[40], 40, to));
                }
                java.util.regex.Matcher m = in.matcher(ui.fx(() -> ((Label) ui.window.status().lookup("#status-rates")).getText()));
                return m.find() && Long.parseLong(m.group(1)) > 0;
            });
        }
        assertEquals(0, ui.console.field().robots().robots().size(), "no robot was heard: the rate is the team messages'");
    }
}
