package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;
import touchline.model.store.PlotStore;
import touchline.proto.Fumanoid;
import touchline.record.Recording;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;
import touchline.transport.SendResult;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Replay is a sandbox, end to end: a match recorded from a simulated robot 8 that heard the
 * GameController say PLAYING (and the GameController's packets themselves) is replayed into a
 * console beside a live simulated robot 8. The live robot gets nothing the replay caused, match
 * mode stays as the live field says, the registry shows the two robots apart, and seeking back
 * starts the replay's plots afresh.
 */
@Tag("integration")
class ReplaySandboxIntegrationTest {

    private static final String PLOT = "demo.plotter";

    private static ConsoleConfig loopback() {
        return ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
    }

    private static byte[] golden(String name) throws Exception {
        try (var in = ReplaySandboxIntegrationTest.class.getResourceAsStream("/golden/gamecontroller/hl12/" + name)) {
            return in.readAllBytes();
        }
    }

    private static long count(List<Envelope> seen, String kind) {
        return seen.stream().filter(e -> e.kind().equals(kind)).count();
    }

    /** Robot 8 streams a plot, then the GameController says PLAYING to it (and to the console), recorded. */
    private static void recordAMatch(Path file) throws Exception {
        List<Envelope> seen = new CopyOnWriteArrayList<>();
        try (Console console = new Console(loopback()).start();
             RobotProcess robot = RobotProcess.robot(8, console.field().port()).start();
             DatagramSocket gc = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            console.recordings().start(file);
            console.field().bus().subscribe(seen::add);
            Await.until("option list", () -> console.field().options().options(8).listReceived());
            assertTrue(console.optionSwitches().set(8, PLOT, true).isSent());
            Await.until("plots", () -> count(seen, "debugPlot") >= 10);
            byte[] playing = golden("04-playing.bin");
            for (int port : new int[] {robot.port(), console.field().port()}) {
                gc.send(new DatagramPacket(playing, playing.length, InetAddress.getLoopbackAddress(), port));
            }
            Await.until("the robot reports PLAYING", () -> console.field().robots().robot(8).orElseThrow().gameState().equals("PLAYING"));
            // during play the robot keeps to the league's debug limit: one status a second, no option data
            long statuses = count(seen, "status");
            Await.until("statuses during play", () -> count(seen, "status") >= statuses + 2);
            console.recordings().stop();
        }
        assertTrue(seen.stream().anyMatch(e -> e.channel() == Channel.GAMECONTROLLER), "the GameController is recorded");
    }

    @Test
    void aReplayBesideALiveRobotOfTheSameNumberSendsItNothingAndDoesNotSilenceTheConsole(@TempDir Path dir)
            throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        Path file = dir.resolve("match.mcap");
        recordAMatch(file);

        List<Envelope> sentLive = new CopyOnWriteArrayList<>();
        List<Envelope> replayed = new CopyOnWriteArrayList<>();
        try (Console console = new Console(loopback()).start();
             RobotProcess robot = RobotProcess.robot(8, console.field().port()).start()) {
            touchline.transport.EnvelopeSink both = e -> {
                if (e.replayed()) {
                    replayed.add(e);
                } else if (e.direction() == Direction.OUT) {
                    sentLive.add(e);
                }
            };
            console.field().bus().subscribe(both);
            console.field().replayStream().subscribe(both);
            Await.until("the live robot's option list", () -> console.field().options().options(8).listReceived());
            // wanted live, and off in every option list the recording holds: a replayed list reaching
            // the option session would make it switch demo.text on again at the live robot
            assertTrue(console.optionSwitches().set(8, "demo.text", true).isSent());
            Await.until("demo.text streams live", () -> streaming(console, "demo.text"));
            sentLive.clear();

            Replay replay = console.replays().open(file);
            assertTrue(console.field().liveListening(), "the replay runs beside live traffic");
            replay.setSpeed(50);
            replay.play();
            Await.until("the replay played to its end", () -> replay.state().finished());

            assertTrue(replayed.stream().anyMatch(e -> e.channel() == Channel.GAMECONTROLLER), () -> "replayed "
                    + replayed.size() + " of " + replay.state() + ": " + replayed.stream().map(Envelope::toString)
                    .filter(t -> !t.contains("debugPlot") && !t.contains("status")).toList() + " problems " + replay.problems());
            assertTrue(replayed.stream().anyMatch(e -> "PLAYING".equals(gameState(e))), "robot 8 reported PLAYING");
            assertTrue(replayed.stream().anyMatch(e -> e.direction() == Direction.OUT), "and the console's requests");
            assertTrue(console.referee().matchMode().mayConsoleSend(), console.referee().matchMode().notice());
            assertFalse(console.referee().matchMode().playIsOn(), "match mode follows the live field only");

            RobotSnapshot live = console.field().robots().robot(8).orElseThrow();
            RobotSnapshot fromReplay = console.field().robots().robot(8, Origin.REPLAY).orElseThrow();
            assertNotEquals("PLAYING", live.gameState(), "the live robot never heard PLAYING");
            assertEquals("PLAYING", fromReplay.gameState());
            assertTrue(fromReplay.label().endsWith("(replay)"), fromReplay.label());
            assertEquals(List.of(Origin.LIVE, Origin.REPLAY),
                    console.field().robots().robots().stream().filter(r -> r.id() == 8).map(RobotSnapshot::origin).toList());

            // the proof that nothing went out: the next live request is the first datagram since the replay began
            SendResult sent = console.optionSwitches().set(8, PLOT, true);
            assertTrue(sent.isSent(), sent.toString());
            Await.until("the live robot streams " + PLOT, 5000, () -> streaming(console, PLOT));
            assertFalse(sentLive.isEmpty());
            Envelope first = sentLive.get(0);
            Fumanoid.DebugOptionRequest request = first.extension(Fumanoid.debugOptionRequest);
            assertNotNull(request, "the first datagram after the replay began: " + first);
            assertEquals(PLOT, request.getName());
            // only that request went to the live robot (again, if the robot took over a second to confirm it:
            // the option session's retry), nothing the recording held
            assertTrue(sentLive.stream().map(e -> e.extension(Fumanoid.debugOptionRequest)).filter(java.util.Objects::nonNull)
                    .allMatch(r -> r.getName().equals(PLOT) && r.getEnable()), "only the live request: " + sentLive);
            assertTrue(console.field().options().options(8, Origin.REPLAY).listReceived(), "the replayed options are shown");

            seekingBackStartsTheReplaysPlotsAfresh(console, replay, file);
            assertSame(console.field().stores().replay().plots(), console.field().stores().plots(), "the views show the open replay");

            console.replays().close();
            assertTrue(console.field().robots().robot(8, Origin.REPLAY).isEmpty(), "the replayed robot goes with the replay");
            assertTrue(console.field().robots().robot(8).orElseThrow().online());
            assertSame(console.field().stores().live().plots(), console.field().stores().plots(), "and the views show live data again");
        }
    }

    private static void seekingBackStartsTheReplaysPlotsAfresh(Console console, Replay replay, Path file)
            throws Exception {
        PlotStore plots = console.field().stores().replay().plots();
        int playedThrough = plots.snapshot(8, PLOT).series().get(0).count();
        // the middle of the plotting (during play the robot keeps to the debug limit and plots nothing)
        long from;
        try (Recording recording = Recording.open(file)) {
            List<Long> plotTimes = new java.util.ArrayList<>();
            Recording.Cursor c = recording.cursor(replay.state().startMicros());
            for (Envelope e = c.next(); e != null; e = c.next()) {
                if (e.kind().equals("debugPlot") && e.robotId() == 8) {
                    plotTimes.add(e.timeMicros());
                }
            }
            from = plotTimes.get(plotTimes.size() / 2);
        }

        replay.seek(from);
        assertNull(plots.snapshot(8, PLOT), "nothing of the first playing is left");
        replay.play();
        Await.until("played to the end again", () -> replay.state().finished());

        PlotStore asIfPlayedFromThere = new PlotStore(PlotStore.DEFAULT_POINTS, replay.state().startMicros());
        try (Recording recording = Recording.open(file)) {
            Recording.Cursor c = recording.cursor(from);
            for (Envelope e = c.next(); e != null; e = c.next()) {
                asIfPlayedFromThere.accept(e);
            }
        }
        PlotStore.SeriesData expected = asIfPlayedFromThere.snapshot(8, PLOT).series().get(0);
        PlotStore.SeriesData got = plots.snapshot(8, PLOT).series().get(0);
        assertTrue(expected.count() < playedThrough, expected.count() + " of " + playedThrough);
        assertEquals(expected.count(), got.count());
        assertArrayEquals(java.util.Arrays.copyOf(expected.x(), expected.count()),
                java.util.Arrays.copyOf(got.x(), got.count()));
        assertArrayEquals(java.util.Arrays.copyOf(expected.y(), expected.count()),
                java.util.Arrays.copyOf(got.y(), got.count()));
        assertTrue(console.field().stores().live().plots().snapshot(8, PLOT) != null, "the live robot's plot is untouched");
    }

    private static boolean streaming(Console console, String option) {
        return console.field().options().options(8).option(option).map(OptionState::streaming).orElse(false);
    }

    private static String gameState(Envelope e) {
        Fumanoid.Status s = e.extension(Fumanoid.status);
        return s == null ? null : s.getGameState();
    }
}
