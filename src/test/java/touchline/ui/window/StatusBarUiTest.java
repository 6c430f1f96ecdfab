package touchline.ui.window;

import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.TreeItem;
import javafx.scene.control.TreeView;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.RobotProcess;
import touchline.testing.UiTest;
import touchline.ui.options.OptionsView;

import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.FramePulse;
import touchline.ui.frame.ViewSource;
import touchline.ui.referee.GameControllerTabDriver;

/**
 * The status bar at a glance, against the real simulated robot and the embedded GameController
 * sending to a loopback socket: a banner while match mode silences the console, the requests
 * waiting now (the running total only in the tooltip), GameController packets in the out rate,
 * and status lines in words.
 */
@UiTest
@Tag("integration")
class StatusBarUiTest {

    private static final int ROBOT = 6;
    private static final String OPTION = "demo.plotter";
    private ConsoleWindowFixture ui;

    private String text(String id) throws Exception {
        return ui.fx(() -> ((Label) ui.window.status().lookup(id)).getText());
    }

    private boolean bannerShown() throws Exception {
        return ui.fx(() -> {
            Node n = ui.window.status().lookup("#status-silence");
            return n.isVisible() && n.isManaged();
        });
    }

    private double outPerSecond() throws Exception {
        Matcher m = Pattern.compile("out (\\d+) pkt/s").matcher(text("#status-rates"));
        return m.find() ? Double.parseDouble(m.group(1)) : -1;
    }

    /** Selects the option's row in the tree by program (no mouse) and toggles it as Space does. */
    @SuppressWarnings("unchecked")
    private void toggleInTree(OptionsView view) throws Exception {
        ui.await(30, () -> {
            TreeView<OptionsView.Row> tree = (TreeView<OptionsView.Row>) view.node().lookup("#options-tree");
            for (TreeItem<OptionsView.Row> r : tree.getRoot().getChildren()) {
                for (TreeItem<OptionsView.Row> o : r.getChildren()) {
                    if (o.getValue().robotId() == ROBOT && o.getValue().option().name().equals(OPTION)) {
                        tree.getSelectionModel().select(o);
                        view.toggleSelected();
                        return true;
                    }
                }
            }
            return false;
        });
    }

    @SuppressWarnings("unchecked")
    private static String robotRow(OptionsView view) {
        TreeView<OptionsView.Row> tree = (TreeView<OptionsView.Row>) view.node().lookup("#options-tree");
        return tree.getRoot().getChildren().stream().map(TreeItem::getValue).filter(r -> r.robotId() == ROBOT)
                .map(OptionsView.Row::label).findFirst().orElse("");
    }

    @Test
    void matchModeShowsABannerCountsWaitingRequestsAndGameControllerPacketsGoOut() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(ROBOT, ui.port()).start();
             DatagramSocket field = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            ui.fxRun(() -> ui.window.shell().restore(List.of()));
            ui.fxRun(() -> ui.window.open("options", ViewSource.NONE));
            ui.await(30, () -> ui.console.field().options().options(ROBOT).listReceived());
            assertFalse(bannerShown(), "no banner while the console may send");
            ui.await(30, () -> text("#status-waiting").equals("0 requests waiting now"));

            GameControllerTabDriver gc = new GameControllerTabDriver(ui);
            gc.start(field);
            ui.await(30, () -> outPerSecond() > 0); // no robot is sent anything: these are GameController packets
            gc.press("#gc-ready");
            gc.press("#gc-set");
            gc.press("#gc-play");
            // READY and SET already silence the console: wait for the banner of PLAYING, not the first one
            ui.await(30, () -> bannerShown() && text("#status-silence").contains("PLAYING"));
            String banner = text("#status-silence");
            assertTrue(banner.contains("match mode") && banner.contains("PLAYING"), banner);

            ui.fxRun(() -> ui.window.open("options", ViewSource.NONE));
            OptionsView options = ui.view(OptionsView.class);
            toggleInTree(options);
            String line = ui.fx(() -> ((Label) options.node().lookup("#options-status")).getText());
            assertTrue(line.startsWith("Switching " + OPTION + " on for robot " + ROBOT + ": held back: match mode, game is PLAYING"),
                    line);
            assertFalse(line.contains("SendResult") || line.contains("outcome="), line);
            ui.await(30, () -> text("#status-waiting").equals("1 request waiting now"));
            ui.await(30, () -> robotRow(options).contains(" · waiting: match mode, game is PLAYING"));
            // the session retries while play is on: the total grows, "waiting now" stays 1
            long total = ui.console.referee().matchMode().heldCount();
            ui.await(30, () -> ui.console.referee().matchMode().heldCount() > total);
            ui.await(30, () -> ui.window.status().lookup("#status-waiting") instanceof Label l
                    && l.getTooltip().getText().contains(ui.console.referee().matchMode().heldCount() + " send attempts held back"));
            assertTrue(text("#status-waiting").equals("1 request waiting now"));
            assertFalse(text("#status-rates").contains("held") || ui.fx(() -> ((Label) ui.window.status().getChildren().get(2))
                    .getText()).contains("held"), "the running total is in the tooltip only");

            gc.press("#gc-stop");
            ui.await(30, () -> !bannerShown());
            ui.await(30, () -> ui.console.field().options().options(ROBOT).option(OPTION).orElseThrow().streaming());
            ui.await(30, () -> text("#status-waiting").equals("0 requests waiting now"));
            ui.await(30, () -> !robotRow(options).contains("waiting"));
            assertFalse(ui.fx(() -> robotRow(options)).contains("held"), ui.fx(() -> robotRow(options)));
        }
    }

    /**
     * Notes stale after play (issue 36, item 6): match mode turns on and off with nothing else
     * heard (play ends by the clock: a source not heard for 5 s no longer counts, and the window
     * idles after 3 s). The idle window follows it instead of keeping the last banner.
     */
    @Test
    void theIdleWindowFollowsMatchModeWithNothingElseHeard() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        FramePulse pulse = ui.window.pulse();
        ui.await(30, () -> !pulse.running() && !bannerShown());
        ui.console.referee().matchMode().observeBelieved(3, "GameController at 127.0.0.1:3838");
        ui.await(30, () -> bannerShown() && text("#status-silence").contains("PLAYING"));
        // nothing more heard: the window idles after 3 s, the GameController's PLAYING goes stale after 5 s
        ui.await(30, () -> !bannerShown());
    }

    @Test
    void aReplayAndPausedLiveTrafficShowTheirBanner() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        assertFalse(bannerShown());
        ui.console.replays().open(Path.of("samples/demo-team.mcap").toAbsolutePath());
        ui.await(30, () -> bannerShown() && text("#status-silence").startsWith("Replay: views show the recording (paused)"));
        ui.console.replays().current().orElseThrow().play();
        ui.await(30, () -> text("#status-silence").startsWith("Replay: views show the recording (playing)"));
        ui.console.field().setLiveListening(false);
        ui.await(30, () -> text("#status-silence").endsWith(" · Live traffic paused: robots on the field are not shown"));
        ui.console.field().setLiveListening(true);
        ui.console.replays().close();
        ui.await(30, () -> !bannerShown());
    }
}
