package touchline.ui.referee;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.Referee;
import touchline.app.SystemClock;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.MatchMode;
import touchline.app.game.SenderPriority;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.game.hsl.Competition;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.testing.Await;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.*;

/**
 * What the GameController tab decides, without a window, over a real referee (no console): which
 * setups start and why the others do not, the game sent to a loopback socket standing in for the
 * robots, a GameController started elsewhere followed, monitors served, the setup remembered, the
 * override's reason, match mode's notice and the sender's priority in words.
 */
class GameControllerTabModelTest {

    private final ManualClock matchClock = new ManualClock(0);
    private final MatchMode matchMode = new MatchMode(matchClock);
    private final Referee referee = new Referee(e -> { }, matchMode, new SystemClock());
    private final AtomicInteger waiting = new AtomicInteger();
    @TempDir
    Path settings;

    @AfterEach
    void stop() {
        referee.stop();
    }

    private GameControllerTabModel model() {
        return new GameControllerTabModel(referee, waiting::get, settings);
    }

    /** The defaults towards {@code robots}, return packets and monitors on ports the system chooses. */
    private static GameSetup towards(DatagramSocket robots, String format) {
        GameSetup d = GameSetup.defaults();
        return new GameSetup(format, d.teamA(), d.teamB(), "127.0.0.1:" + robots.getLocalPort(), "0", false,
                d.competition(), d.fieldA(), d.keeperA(), d.fieldB(), d.keeperB(), "0");
    }

    /** Asks {@code model} to start {@code setup}, then waits for the frame it runs at: its line. */
    private static String run(GameControllerTabModel model, GameSetup setup) throws InterruptedException {
        assertEquals("starting…", model.start(setup), "a start only asks");
        java.util.concurrent.atomic.AtomicReference<Optional<String>> line = new java.util.concurrent.atomic.AtomicReference<>();
        Await.until("the start's line", () -> line.updateAndGet(was -> model.started()).isPresent());
        return line.get().orElseThrow();
    }

    private static GameSetup with(GameSetup s, String teamA, String destinations, TeamColour fieldB) {
        return new GameSetup(s.format(), teamA, s.teamB(), destinations, s.returnPort(), s.realtime(), s.competition(),
                s.fieldA(), s.keeperA(), fieldB, s.keeperB(), s.monitorPort());
    }

    private static DatagramSocket robots() throws Exception {
        DatagramSocket s = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        s.setSoTimeout((int) Await.FLOOR_MILLIS);
        return s;
    }

    @Test
    void aSetupThatCannotStartSaysWhyAndStartsNothing() throws Exception {
        GameControllerTabModel model = model();
        try (DatagramSocket robots = robots()) {
            GameSetup hsl = towards(robots, "hsl20");
            assertEquals("choose a format", model.start(towards(robots, "hl99")));
            assertEquals("give at least one destination", model.start(with(hsl, "13", " , ", TeamColour.BLUE)));
            assertEquals("team numbers and ports are whole numbers: For input string: \"x\"",
                    model.start(with(hsl, "x", hsl.destinations(), TeamColour.BLUE)));
            assertEquals("cannot start: the two teams need different numbers",
                    model.start(with(hsl, "7", hsl.destinations(), TeamColour.BLUE)));
            assertEquals("cannot start: a team's field players wear the other goalkeeper's colour",
                    model.start(with(hsl, "13", hsl.destinations(), TeamColour.PURPLE)));
            assertTrue(referee.gameController().isEmpty());
            assertNull(model.shown());
            assertFalse(model.follow(), "nothing runs, nothing to show");
        }
    }

    @Test
    void startsAnHlGameTowardsTheRobotsShowsItAndStops() throws Exception {
        GameControllerTabModel model = model();
        try (DatagramSocket robots = robots()) {
            assertEquals("", run(model, towards(robots, "hl12")));
            EmbeddedGameController gc = referee.gameController().orElseThrow();
            assertSame(gc, model.shown());
            assertFalse(model.follow(), "started here: already shown");
            assertEquals("hl12 to [/127.0.0.1:" + robots.getLocalPort() + "]", model.header());
            assertEquals("", model.monitors(), "no monitors in the HL formats");
            DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
            robots.receive(p);
            assertEquals(688, p.getLength(), "HL v12 as chosen");
            assertEquals("stopping…", model.stop(), "a stop only asks");
            assertTrue(referee.gameController().isEmpty());
            assertNull(model.shown());
            assertFalse(model.follow());
            Await.until("the stop's line", () -> model.stopped().map("stopped"::equals).orElse(false));
        }
    }

    @Test
    void aGameControllerStartedOrStoppedElsewhereIsFollowedWithoutAMonitorsLine() throws Exception {
        GameControllerTabModel model = model();
        try (DatagramSocket robots = robots()) {
            assertEquals("", run(model, towards(robots, "hsl20")));
            assertTrue(model.monitors().startsWith("monitors register on UDP "), model.monitors());
            GcConfig config = new GcConfig(GcProfile.HL12, false,
                    List.of(new InetSocketAddress("127.0.0.1", robots.getLocalPort())), null,
                    new InetSocketAddress("127.0.0.1", 0), null, GcConfig.INTERVAL_MS, false);
            EmbeddedGameController elsewhere = referee.start(
                    new Game(LeagueParams.hlSimulationKidSize(), 3, 1, 4, 0, referee.gameClock()), config);
            assertTrue(model.follow());
            assertSame(elsewhere, model.shown());
            assertEquals("", model.monitors(), "whoever started it serves monitors or not");
            assertFalse(model.follow());
            referee.stop();
            assertTrue(model.follow());
            assertNull(model.shown());
        }
    }

    @Test
    void anHslGameServesMonitorsAndABusyPortCostsOnlyThat() throws Exception {
        GameControllerTabModel model = model();
        try (DatagramSocket robots = robots(); DatagramSocket taken = new DatagramSocket(
                new InetSocketAddress("127.0.0.1", 0))) {
            GameSetup s = towards(robots, "hsl20");
            assertEquals("", run(model, s));
            String port = model.monitors().substring("monitors register on UDP ".length()).split(";")[0];
            assertNotEquals("0", port, "the port the system chose");
            Await.until("the monitors' count", () -> model.monitors().contains("; "));
            assertEquals("monitors register on UDP " + port + "; 0 of 32 registered, 0 refused", model.monitors());
            GameSetup busy = new GameSetup(s.format(), s.teamA(), s.teamB(), s.destinations(), s.returnPort(),
                    s.realtime(), s.competition(), s.fieldA(), s.keeperA(), s.fieldB(), s.keeperB(),
                    Integer.toString(taken.getLocalPort()));
            assertEquals("", run(model, busy), "the game starts without monitors");
            assertTrue(model.monitors().startsWith("no monitors: cannot listen on UDP " + taken.getLocalPort() + " ("),
                    model.monitors());
        }
    }

    @Test
    void theSetupIsRememberedForTheNextStartAndANameNoLongerKnownKeepsTheDefault() throws Exception {
        assertEquals(GameSetup.defaults(), model().initialSetup(), "nothing remembered yet");
        try (DatagramSocket robots = robots()) {
            GameSetup d = towards(robots, "hsl19");
            GameSetup s = new GameSetup("hsl19", "21", "22", d.destinations(), "0", false, Competition.LARGE_FOUNDATION,
                    TeamColour.GREEN, TeamColour.ORANGE, TeamColour.WHITE, TeamColour.BLACK, "0");
            assertEquals("", run(model(), s));
            GameSetup again = model().initialSetup();
            assertEquals(new GameSetup("hsl19", "21", "22", d.destinations(), "0", true, Competition.LARGE_FOUNDATION,
                    TeamColour.GREEN, TeamColour.ORANGE, TeamColour.WHITE, TeamColour.BLACK, "0"), again,
                    "all but the real-time choice, which is on at every start");
        }
        Path file = settings.resolve("gamecontroller.properties");
        Files.writeString(file, Files.readString(file).replace("colourA=GREEN", "colourA=TARTAN")
                .replace("format=hsl19", "format=hsl99"));
        GameSetup edited = model().initialSetup();
        assertEquals(GameSetup.defaults().fieldA(), edited.fieldA());
        assertEquals(GameSetup.defaults().format(), edited.format());
        assertEquals("21", edited.teamA());
    }

    @Test
    void anOverrideNeedsAReasonAndIsSwitchedWithIt() {
        GameControllerTabModel model = model();
        assertEquals(Optional.of("An override needs a reason; it is logged."), model.override(true, "  "));
        assertFalse(matchMode.isOverridden());
        assertEquals(Optional.empty(), model.override(true, " practice on the far field "));
        assertTrue(matchMode.isOverridden());
        assertEquals("practice on the far field", matchMode.overrideLog().get(0).reason());
        assertEquals(Optional.empty(), model.override(false, ""), "switching off needs no reason");
        assertFalse(matchMode.isOverridden());
    }

    @Test
    void theMatchNoticeSaysWhenNoGameIsOnAndCountsTheRequestsWaiting() {
        GameControllerTabModel model = model();
        assertEquals(new GameControllerTabModel.Notice("Match mode: no game on; the console may talk to the robots.",
                false), model.matchNotice());
        matchMode.observe(GameControlData.STATE_PLAYING, "GameController at 127.0.0.1:3838");
        waiting.set(1);
        GameControllerTabModel.Notice notice = model.matchNotice();
        assertTrue(notice.warning());
        assertEquals(matchMode.notice() + "; 1 request waiting now", notice.text());
        waiting.set(3);
        assertTrue(model.matchNotice().text().endsWith("; 3 requests waiting now"), model.matchNotice().text());
    }

    @Test
    void theSendersPriorityInWords() {
        assertEquals("Sender: real-time priority (500 ms cadence held under load)",
                GameControllerTabModel.priorityText(new SenderPriority(SenderPriority.Kind.REAL_TIME, "")));
        assertEquals("Sender: normal priority",
                GameControllerTabModel.priorityText(new SenderPriority(SenderPriority.Kind.NOT_REQUESTED, "")));
        assertEquals("Sender: starting",
                GameControllerTabModel.priorityText(new SenderPriority(SenderPriority.Kind.STARTING, "")));
        assertEquals("Sender: normal priority, real-time refused (no CAP_SYS_NICE)",
                GameControllerTabModel.priorityText(new SenderPriority(SenderPriority.Kind.REFUSED, "no CAP_SYS_NICE")));
    }
}
