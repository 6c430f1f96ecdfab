package touchline.ui.replay;

import javafx.embed.swing.SwingFXUtils;
import javafx.geometry.Bounds;
import javafx.geometry.Point2D;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import javafx.stage.Stage;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.testfx.api.FxRobot;
import org.testfx.api.FxToolkit;
import org.testfx.util.WaitForAsyncUtils;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.record.PlayerState;
import touchline.record.Recording;
import touchline.record.TimelineEvent;
import touchline.testing.UiTest;
import touchline.transport.UdpConfig;
import touchline.ui.window.ConsoleWindow;
import touchline.ui.window.Shell;
import touchline.ui.window.UiSettings;
import touchline.ui.frame.ViewSource;

import javax.imageio.ImageIO;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

/**
 * The Record &amp; replay view in the real console window (headless Monocle): the sample
 * recording opened through the view plays into the model, its events are on the timeline,
 * seeking by timeline and by event lands where it should, a broken file is reported and the
 * console carries on, recording writes a file.
 */
@UiTest
class ReplayViewTest {

    static final Path SAMPLE = Path.of("samples/demo-team.mcap").toAbsolutePath();

    @TempDir
    Path dir;
    private Console console;
    private ConsoleWindow window;
    private ReplayView view;
    private final FxRobot robot = new FxRobot();

    @BeforeEach
    void open() throws Exception {
        console = new Console(ConsoleConfig.defaults().withUdp(
                UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
        Stage stage = FxToolkit.registerPrimaryStage();
        window = fx(() -> new ConsoleWindow(console, new UiSettings(dir, true, false)).show(stage));
        view = fx(() -> {
            // the replay view alone: the clicks below need its controls on screen, not scrolled away
            // below the default layout's other views
            window.shell().restore(java.util.List.of());
            window.open("replay", ViewSource.NONE);
            return window.shell().openViews().stream().map(Shell.OpenView::view)
                    .filter(ReplayView.class::isInstance).map(ReplayView.class::cast).findFirst().orElseThrow();
        });
        awaitShown();
    }

    @AfterEach
    void close() throws Exception {
        fx(() -> {
            window.pulse().stop();
            window.scene().getWindow().hide();
            return null;
        });
        FxToolkit.cleanupStages();
        console.close();
    }

    /**
     * Issue 36 item 5: a seek while paused shows the state at the play head: the replayed robots and
     * every store the views read hold the newest of each kind at or before it (it said "0 envelopes").
     */
    @Test
    void aSeekWhilePausedShowsTheStateAtThePlayHead() throws Exception {
        openFile(SAMPLE);
        List<TimelineEvent> events = shownEvents();
        robot.clickOn("#replay-live"); // replay alone
        robot.clickOn("#replay-next-goal");
        TimelineEvent goal = events.stream().filter(e -> e.type() == TimelineEvent.Type.GOAL).findFirst().orElseThrow();
        await(5, () -> state().positionMicros() == goal.timeMicros());
        assertFalse(state().playing(), "never played");
        await(20, () -> console.field().robots().robots().size() == 3);
        await(20, () -> fx(() -> window.context().stores().network().size()) > 0
                && fx(() -> window.context().stores().text().size()) > 0);
        await(20, () -> !robot.lookup("#replay-position").queryAs(Label.class).getText().contains(" 0 envelopes"));
        assertTrue(console.field().robots().robots().stream().allMatch(r -> r.replayed()), "the replay's robots");
    }

    @Test
    void theSamplePlaysIntoTheModelAndSeeksToTheGoal() throws Exception {
        openFile(SAMPLE);
        List<TimelineEvent> events = shownEvents();
        List<String> ticks = fx(() -> events.stream().map(this::tickSeen).toList());
        assertEquals(java.util.Set.of("GOAL", "STATE_CHANGE", "ROBOT_LOST"), ticks.stream().filter(t -> t.startsWith("yes "))
                        .map(t -> t.split(" ")[1]).collect(java.util.stream.Collectors.toSet()),
                () -> "goal, state changes and the robot drop-out are on the timeline, each in its colour: " + ticks);
        TimelineEvent goal = events.stream().filter(e -> e.type() == TimelineEvent.Type.GOAL).findFirst().orElseThrow();

        robot.clickOn("#replay-live"); // replay alone: the model's clock follows the replay
        assertFalse(console.field().liveListening());
        // 4x: the 180 s sample lasts 45 s, so a loaded machine still catches it playing and pauses it
        // before its end (at 50x it reached its end before the check in a CI run beside other builds)
        chooseSpeed(4.0);
        robot.clickOn("#replay-play");
        await(20, () -> console.field().robots().robots().size() == 3);
        await(20, () -> state().playing() && state().positionMicros() - state().startMicros() > 10_000_000L);
        assertEquals(4.0, state().speed());
        robot.clickOn("#replay-play"); // pause
        await(5, () -> !state().playing());

        // click the very left of the timeline: back to the start
        Bounds b = fx(() -> timeline().localToScreen(timeline().getBoundsInLocal()));
        robot.clickOn(new Point2D(b.getMinX() + TimelineCanvas.PAD, b.getCenterY()));
        await(5, () -> state().positionMicros() == state().startMicros());

        robot.clickOn("#replay-next-goal");
        await(5, () -> state().positionMicros() == goal.timeMicros());
        String at = TimelineCanvas.clock(goal.timeMicros() - state().startMicros());
        await(5, () -> robot.lookup("#replay-position").queryAs(Label.class).getText().startsWith(at + " /"));

        // playing, "next state change" lands on the event (plus at most a frame's worth of play); the
        // event is 5 s before the end, so the replay then plays to its end and stops by itself (a
        // click to pause could come after the end on a loaded machine and start it again)
        TimelineEvent finished = events.stream().filter(e -> e.type() == TimelineEvent.Type.STATE_CHANGE
                && e.timeMicros() > goal.timeMicros()).findFirst().orElseThrow();
        robot.clickOn("#replay-play");
        robot.clickOn("#replay-next-state");
        await(20, () -> state().positionMicros() >= finished.timeMicros());
        await(20, () -> !state().playing());

        // loop A at the goal, B ten seconds later
        robot.clickOn(new Point2D(fx(() -> timeline().localToScreen(xOf(goal.timeMicros()), 0).getX()), b.getCenterY()));
        await(5, () -> Math.abs(state().positionMicros() - goal.timeMicros()) < 2_000_000);
        long a = state().positionMicros();
        robot.clickOn("#replay-loop-a");
        robot.clickOn(new Point2D(fx(() -> timeline().localToScreen(xOf(goal.timeMicros() + 10_000_000), 0).getX()),
                b.getCenterY()));
        await(5, () -> state().positionMicros() > a + 5_000_000);
        long bTime = state().positionMicros();
        robot.clickOn("#replay-loop-b");
        await(5, () -> state().loopFromMicros() == a && state().loopToMicros() == bTime);

        robot.clickOn("#replay-loop-clear");
        await(5, () -> state().loopFromMicros() < 0);
        robot.clickOn("#replay-close");
        await(5, () -> console.replays().current().isEmpty());
        await(5, () -> robot.lookup("#replay-position").queryAs(Label.class).getText().equals("No recording open."));
    }

    /**
     * Issue 36 item 9: "Opened demo-team.mcap." goes with the replay when it is closed; an error
     * about a file that could not be opened stays (it is not about the replay that closed).
     */
    @Test
    void closingTheReplayClearsItsOpenedMessage() throws Exception {
        openFile(SAMPLE);
        await(20, () -> message().equals("Opened demo-team.mcap."));
        await(20, () -> fx(() -> !robot.lookup("#replay-play").query().isDisabled()));
        robot.clickOn("#replay-close");
        await(5, () -> console.replays().current().isEmpty());
        // the position line and the message are updated in the same frame
        await(5, () -> robot.lookup("#replay-position").queryAs(Label.class).getText().equals("No recording open."));
        assertEquals("", message());

        // opening a missing file closes the open replay first: its error stays
        openFile(SAMPLE);
        await(20, () -> message().equals("Opened demo-team.mcap."));
        openFile(dir.resolve("missing.mcap"));
        await(10, () -> message().contains("Cannot replay missing.mcap"));
        await(5, () -> robot.lookup("#replay-position").queryAs(Label.class).getText().equals("No recording open."));
        assertTrue(message().contains("Cannot replay missing.mcap"), message());
    }

    @Test
    void aBrokenFileIsReportedAndTheConsoleCarriesOn() throws Exception {
        Path junk = dir.resolve("junk.mcap");
        byte[] bytes = new byte[64];
        new Random(7).nextBytes(bytes);
        Files.write(junk, bytes);
        openFile(junk);
        await(10, () -> message().contains("Cannot replay junk.mcap") && message().contains("not an MCAP"));
        assertTrue(console.replays().current().isEmpty());

        openFile(dir.resolve("missing.mcap"));
        await(10, () -> message().contains("Cannot replay missing.mcap"));

        // a file cut in the middle: replays up to the cut, the problem is listed
        Path cut = dir.resolve("cut.mcap");
        byte[] whole = Files.readAllBytes(SAMPLE);
        Files.write(cut, java.util.Arrays.copyOf(whole, whole.length / 2));
        openFile(cut);
        await(20, () -> !robot.lookup("#replay-problems").queryAs(ListView.class).getItems().isEmpty());
        assertFalse(shownEvents().isEmpty());
        assertTrue(window.scene().getWindow().isShowing());
    }

    @Test
    void whatWasSkippedIsShownInThePanelAsReplaySaysIt() throws Exception {
        Path foreign = dir.resolve("foreign.mcap");
        try (touchline.record.McapWriter w = new touchline.record.McapWriter(foreign, 4096)) {
            int schema = w.addSchema("std_msgs/msg/String", "ros2msg", "string data".getBytes());
            int chatter = w.addChannel(schema, "/chatter", "cdr", java.util.Map.of());
            int score = w.addChannel(0, "/score", "json", java.util.Map.of());
            int monster = w.addChannel(w.addSchema("Monster", "flatbuffer", new byte[]{1}), "/monster", "flatbuffer",
                    java.util.Map.of());
            w.addMetadata("match", java.util.Map.of("field", "B"));
            for (int i = 0; i < 25; i++) {
                long t = 1_700_000_000_000_000_000L + i * 10_000_000L;
                w.addMessage(chatter, t, t, new byte[]{0, 1, 0, 0, 1, 0, 0, 0, 0});
                w.addMessage(score, t, t, ("{\"home\": " + i + "}").getBytes());
                w.addMessage(monster, t, t, new byte[]{4, 0, 0, 0});
            }
        }
        openFile(foreign);
        String said = "skipped 25 messages of 1 channel: /monster (flatbuffer/flatbuffer: encoding not supported) 25";
        await(20, () -> robot.lookup("#replay-notes").queryAs(Label.class).getText()
                .equals("⚠ 25 messages of 1 channel skipped"));
        Label badge = robot.lookup("#replay-notes").queryAs(Label.class);
        assertEquals(said, fx(() -> badge.getTooltip().getText()));
        java.util.List<?> items = fx(() -> java.util.List.copyOf(
                robot.lookup("#replay-problems").queryAs(ListView.class).getItems()));
        assertEquals(java.util.List.of("⚠ " + said, "• metadata match: field=B (listed, not played)"), items);
        // the JSON and the ROS 2 channel play into every view without a fault (a fault would be a note of its own)
        chooseSpeed(50.0);
        robot.clickOn("#replay-play");
        await(20, () -> state().finished());
        assertEquals(50, state().emitted());
        await(5, () -> robot.lookup("#replay-problems").queryAs(ListView.class).getItems().equals(items));
        // the same sentence replay prints
        try (Recording r = Recording.open(foreign)) {
            touchline.record.Player p = new touchline.record.Player(r, e -> { }, new touchline.app.SystemClock());
            assertEquals(50, p.runToEnd());
            assertEquals(java.util.List.of(said), r.notes().lines());
        }
    }

    @Test
    void recordingWritesAFileThatReplays() throws Exception {
        Path out = dir.resolve("rec/session.mcap");
        fx(() -> {
            robot.lookup("#record-path").queryAs(TextField.class).setText(out.toString());
            return null;
        });
        robot.clickOn("#record-toggle");
        await(10, () -> robot.lookup("#record-counters").queryAs(Label.class).getText().startsWith("Recording:"));
        openFile(SAMPLE);
        shownEvents();
        chooseSpeed(50.0);
        robot.clickOn("#replay-play");
        // the recorder takes the live stream, never the replay (issue 38): the field's traffic goes on
        // beside the replay, here the sample's envelopes as if heard live (without their field's
        // addresses, so nothing is ever sent there)
        try (Recording sample = Recording.open(SAMPLE)) {
            Recording.Cursor c = sample.cursor(sample.startMicros());
            for (touchline.transport.Envelope e = c.next(); e != null; e = c.next()) {
                console.field().bus().accept(new touchline.transport.Envelope(e.timeMicros(), e.direction(), e.channel(), null,
                        e.robotId(), e.kind(), e.message(), e.raw(), e.error()));
            }
        }
        await(20, () -> console.recordings().current().map(s -> s.written() > 1000).orElse(false));
        robot.clickOn("#record-toggle");
        await(10, () -> robot.lookup("#record-counters").queryAs(Label.class).getText().startsWith("Stopped:"));
        try (Recording r = Recording.open(out, new touchline.protocol.MessageKinds())) {
            assertTrue(r.problems().isEmpty(), () -> "a complete file: " + r.problems());
            assertTrue(r.endMicros() > r.startMicros());
        }
        assertTrue(fx(() -> robot.lookup("#record-path").queryAs(TextField.class).getText())
                .startsWith(Path.of("recordings", "touchline-").toString()), "the next recording gets a new name");
    }

    @Test
    void aTeamSchemaLoadsFromTheView() throws Exception {
        Path desc = dir.resolve("team.desc");
        Files.write(desc, touchline.app.TeamSchemasTest.teamSet("teamBall", 1042).toByteArray());
        fx(() -> {
            view.loadSchema(desc);
            return null;
        });
        await(10, () -> robot.lookup("#schema-list").queryAs(ListView.class).getItems().stream()
                .anyMatch(i -> i.toString().startsWith("✔ teamBall = 1042")));
        assertTrue(console.field().kinds().byName("teamBall").isPresent());
    }

    /**
     * Renders the view mid-replay for docs/screenshots/replay.png: a tool, not a test, so it is
     * tagged "screenshot" and left out of the suite (pom.xml); run it with
     * {@code mvn test -Dtouchline.test.excludedGroups=none -Dtest=ReplayViewTest#screenshot
     * -Dtouchline.replay.screenshot=docs/screenshots/replay.png}.
     */
    @Test
    @org.junit.jupiter.api.Tag("screenshot")
    void screenshot() throws Exception {
        String target = System.getProperty("touchline.replay.screenshot", "target/replay.png");
        fx(() -> {
            window.shell().restore(java.util.List.of(new touchline.ui.window.LayoutNode.Branch(true,
                    java.util.List.of(0.62), java.util.List.of(
                    new touchline.ui.window.LayoutNode.Leaf(0, java.util.List.of(new touchline.ui.window.LayoutNode.Entry("replay", ""))),
                    new touchline.ui.window.LayoutNode.Leaf(0, java.util.List.of(new touchline.ui.window.LayoutNode.Entry("robots", "")))))));
            view = window.shell().openViews().stream().map(Shell.OpenView::view)
                    .filter(ReplayView.class::isInstance).map(ReplayView.class::cast).findFirst().orElseThrow();
            return null;
        });
        awaitShown();
        robot.clickOn("#replay-live");
        openFile(Path.of("samples/demo-team.mcap")); // relative, as a user would type it
        List<TimelineEvent> events = shownEvents();
        chooseSpeed(50.0);
        robot.clickOn("#replay-play");
        await(20, () -> state().positionMicros() - state().startMicros() > 60_000_000L);
        robot.clickOn("#replay-play");
        await(5, () -> !state().playing());
        // a loop around the goal, then play on at normal speed from just before it
        long goal = events.stream().filter(e -> e.type() == TimelineEvent.Type.GOAL).findFirst().orElseThrow().timeMicros();
        clickTimeline(goal - 20_000_000);
        robot.clickOn("#replay-loop-a");
        clickTimeline(goal + 15_000_000);
        robot.clickOn("#replay-loop-b");
        clickTimeline(goal - 8_000_000);
        chooseSpeed(1.0);
        robot.clickOn("#replay-play");
        robot.moveTo("#replay-next-goal");
        Thread.sleep(500); // let the robot table's half-second refresh catch up before the picture
        Path png = Path.of(target);
        Files.createDirectories(png.toAbsolutePath().getParent());
        fx(() -> ImageIO.write(SwingFXUtils.fromFXImage(window.scene().snapshot(null), null), "png", png.toFile()));
    }

    /** The view sits in a scroll pane, whose content joins the scene with its skin (a pulse later). */
    private void awaitShown() throws Exception {
        await(10, () -> robot.lookup("#replay-live").tryQuery().map(n -> n.getScene() != null).orElse(false));
    }

    @Test
    void severalFilesOpenAsOneSessionAndTheTimelineSaysHowTheirClocksWereAligned() throws Exception {
        // robot 2's own log: its traffic and the GameController packets it heard, on a clock 0.8 s ahead
        Path robotLog = dir.resolve("robot2.mcap");
        try (Recording sample = Recording.open(SAMPLE);
             touchline.record.EnvelopeWriter w = new touchline.record.EnvelopeWriter(robotLog,
                     touchline.record.EnvelopeWriter.Options.defaults())) {
            Recording.Cursor c = sample.cursor(Long.MIN_VALUE);
            for (touchline.transport.Envelope e = c.next(); e != null; e = c.next()) {
                if (e.robotId() == 2 || e.channel() == touchline.transport.Channel.GAMECONTROLLER) {
                    w.write(new touchline.transport.Envelope(e.timeMicros() + 800_000, e.direction(), e.channel(),
                            e.peer(), e.robotId(), e.kind(), e.message(), e.raw(), e.error()));
                }
            }
        }
        openText(SAMPLE + "; " + robotLog);
        await(20, () -> filesText().contains("robot2.mcap +0.800 s"));
        String text = fx(this::filesText);
        assertTrue(text.startsWith("demo-team.mcap reference clock"), text);
        assertTrue(text.matches("(?s).*robot2\\.mcap \\+0\\.800 s, \\d+ GC packets matched, agree within 1 ms.*"), text);
        try (Recording sample = Recording.open(SAMPLE)) {
            assertEquals(sample.startMicros(), state().startMicros(), "the robot's log lies inside the laptop's on its clock");
        }

        // a given offset wins over the packets
        openText(SAMPLE + "; " + robotLog + "=+0.5");
        await(20, () -> filesText().contains("robot2.mcap +0.500 s (given)"));
    }

    private void clickTimeline(long micros) throws Exception {
        Point2D p = fx(() -> timeline().localToScreen(xOf(micros), timeline().getLayoutBounds().getHeight() / 2));
        robot.clickOn(p);
    }

    /** Types {@code text} into the file field and presses Enter in it. */
    private void openText(String text) throws Exception {
        fx(() -> {
            TextField field = robot.lookup("#replay-path").queryAs(TextField.class);
            field.setText(text);
            field.fireEvent(new javafx.event.ActionEvent());
            return null;
        });
    }

    /**
     * The open replay's events once the timeline shows them: the position line counts them then (it
     * says "reading events…" while the scan thread reads them).
     */
    private List<TimelineEvent> shownEvents() throws Exception {
        await(20, () -> robot.lookup("#replay-position").queryAs(Label.class).getText().matches(".*  ·  [1-9][0-9,]* events"));
        return console.replays().current().orElseThrow().events();
    }

    private javafx.scene.layout.Region timeline() {
        return robot.lookup("#replay-timeline").queryAs(javafx.scene.layout.Region.class);
    }

    /** The x of a time on the timeline now (FX thread), as the timeline maps it. */
    private double xOf(long micros) throws Exception {
        PlayerState s = state();
        return TimelineCanvas.xAt(micros, s.startMicros(), s.endMicros(), timeline().getWidth());
    }

    /** What the timeline shows at the event's tick: "yes"/"no" and the colours seen (FX thread). */
    private String tickSeen(TimelineEvent e) {
        try {
            javafx.scene.layout.Region node = timeline();
            int x = (int) Math.round(xOf(e.timeMicros()));
            int y = e.type() == TimelineEvent.Type.ROBOT_LOST ? (int) node.getHeight() - 4 : 4;
            javafx.scene.image.PixelReader pixels = node.snapshot(null, null).getPixelReader();
            javafx.scene.paint.Color want = TimelineCanvas.colour(e.type());
            StringBuilder seen = new StringBuilder();
            boolean found = false;
            for (int dx = -1; dx <= 1; dx++) {
                javafx.scene.paint.Color c = pixels.getColor(x + dx, y);
                seen.append(' ').append(c);
                found |= Math.abs(c.getRed() - want.getRed()) < 0.05 && Math.abs(c.getGreen() - want.getGreen()) < 0.05
                        && Math.abs(c.getBlue() - want.getBlue()) < 0.05;
            }
            return (found ? "yes " : "no ") + e.type() + " at " + x + "," + y + " want " + want + " saw" + seen;
        } catch (Exception ex) {
            throw new AssertionError(ex);
        }
    }

    private void openFile(Path file) throws Exception {
        fx(() -> {
            robot.lookup("#replay-path").queryAs(TextField.class).setText(file.toString());
            // fired, not clicked: a mouse move across the row lands on "Add file…" (a native file
            // chooser Monocle cannot show) when the row is still being laid out under load
            robot.lookup("#replay-open").queryAs(javafx.scene.control.Button.class).fire();
            return null;
        });
    }

    @SuppressWarnings("unchecked")
    private void chooseSpeed(double speed) throws Exception {
        fx(() -> {
            ((ComboBox<Double>) robot.lookup("#replay-speed").query()).setValue(speed);
            return null;
        });
    }

    private String message() throws Exception {
        return fx(() -> robot.lookup("#replay-message").queryAs(Label.class).getText());
    }

    private PlayerState state() throws Exception {
        return console.replays().current().orElseThrow().state();
    }

    /** The per-file alignment lines under the timeline as shown (FX thread), "" while hidden. */
    private String filesText() {
        javafx.scene.control.Label files = (javafx.scene.control.Label) view.node().lookup("#replay-files");
        return files.isVisible() ? files.getText() : "";
    }

    /** Never shorter than {@link touchline.testing.Await#FLOOR_MILLIS}: a loaded machine must not fail a wait. */
    private void await(int seconds, Callable<Boolean> condition) throws Exception {
        long millis = Math.max(seconds * 1000L, touchline.testing.Await.FLOOR_MILLIS);
        WaitForAsyncUtils.waitFor(millis, TimeUnit.MILLISECONDS, () -> fx(condition));
    }
}
