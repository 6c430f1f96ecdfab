package touchline.app.game;

import touchline.game.ManualClock;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class MatchModeTest {

    private final ManualClock clock = new ManualClock(0);
    private final MatchMode mode = new MatchMode(clock);

    @Test
    void allowsInInitialAndBlocksADebugRequestDuringPlaying() {
        mode.observe(0, "gc");
        assertTrue(mode.mayConsoleSend());
        assertFalse(mode.hold("debug option vision.ball"));
        assertEquals("", mode.notice());
        mode.observe(3, "gc");
        assertFalse(mode.mayConsoleSend());
        assertTrue(mode.hold("debug option vision.ball"));
        assertEquals(List.of("debug option vision.ball"), mode.heldBack());
        assertTrue(mode.notice().contains("PLAYING"), mode.notice());
        assertTrue(mode.notice().contains("1 send attempt held back since play began (retries included)"), mode.notice());
    }

    /**
     * "706 request(s) held back" beside "0 requests waiting now" read as a contradiction: the notice
     * counts attempts (a retry each second counts again) since this play began, and says so.
     */
    @Test
    void theNoticeCountsAttemptsSincePlayBeganAndSaysThatRetriesCount() {
        mode.observe(3, "gc");
        for (int i = 0; i < 5; i++) {
            mode.hold("console request");
        }
        assertTrue(mode.notice().endsWith("5 send attempts held back since play began (retries included)"), mode.notice());
        mode.observe(4, "gc");
        clock.advance(MatchMode.PLAY_MEMORY_MS + 1);
        assertEquals("", mode.notice());
        mode.observe(3, "gc");
        mode.hold("console request");
        assertTrue(mode.notice().endsWith("1 send attempt held back since play began (retries included)"), mode.notice());
        assertEquals(6, mode.heldCount(), "the total since the console started stays");
    }

    /** Our own game is ours, not "robot 1"'s: a robot only repeats what it heard from a GameController. */
    @Test
    void aGameControllerIsNamedBeforeTheRobotsThatRepeatIt() {
        for (int robot = 1; robot <= 5; robot++) {
            mode.observeReported(3, robot);
        }
        mode.observe(3, "this console's GameController");
        assertEquals("game is PLAYING (this console's GameController)", mode.play());
    }

    /**
     * The embedded GameController stopped mid-game: robots go on reporting PLAYING, the last state
     * they heard. The console stays silent (the robots may still play) and says why and what to do.
     */
    @Test
    void robotsStillReportingPlayWithoutAGameControllerGetAHint() {
        mode.observe(3, "this console's GameController");
        mode.observeReported(3, 1);
        clock.advance(MatchMode.STALE_MS + 1);
        mode.observeReported(3, 1);
        assertFalse(mode.mayConsoleSend());
        String play = mode.play();
        assertTrue(play.startsWith("game is PLAYING (robot 1 reports it; no GameController heard for"), play);
        assertTrue(play.contains("start a GameController and finish the game, or override match mode"), play);
    }

    /**
     * Notes stale after play (issue 36, item 6): the believed GameController said FINISHED, and a
     * robot switched off after the whistle had last reported PLAYING. Its report repeated the game
     * that has since ended: the console may talk again once the GameController's own claim of play
     * is old, not 5 s after the robot's last report; a report of play after the FINISHED still counts.
     */
    @Test
    void aRobotsReportOfPlayEndsWithTheBelievedGameControllersFinished() {
        mode.observeBelieved(3, "this console's GameController");
        mode.observeReported(3, 1);
        clock.advance(100);
        mode.observeBelieved(4, "this console's GameController");
        long flips = mode.changes();
        clock.advance(MatchMode.PLAY_MEMORY_MS + 1);
        assertTrue(mode.mayConsoleSend(), mode.play());
        assertEquals("", mode.notice());
        assertEquals(flips + 1, mode.changes(), "the end of play by the clock alone is a change an idle window sees");
        mode.observeReported(3, 2);
        assertFalse(mode.mayConsoleSend(), "a robot still reporting play after the FINISHED keeps the console silent");
    }

    /**
     * Sources are kept for the last {@link RecentSources#CAPACITY} heard: a flood of FINISHED from
     * thousands of made-up sources pushes the GameController's PLAYING out of what was heard last,
     * yet its claim of play holds the console silent all the same.
     */
    @Test
    void aFloodOfSourcesNeverLiftsTheSilence() {
        mode.observe(3, "GameController at 10.0.0.2:3838");
        for (int port = 1; port <= 10_000; port++) {
            mode.observe(4, "10.0.0.66:" + port);
        }
        assertFalse(mode.mayConsoleSend());
        assertTrue(mode.play().contains("10.0.0.2:3838"), mode.play());
        clock.advance(MatchMode.PLAY_MEMORY_MS + 1);
        assertTrue(mode.mayConsoleSend(), "play is over once the claim is old");
    }

    @Test
    void aSourceTableKeepsTheLastHeardAndCountsTheForgotten() {
        RecentSources<Integer> table = new RecentSources<>(3);
        for (int i = 1; i <= 5; i++) {
            table.put("s" + i, i);
        }
        table.put("s3", 33); // heard again: now the newest
        table.put("s6", 6);
        assertEquals(List.of(5, 33, 6), table.values());
        assertEquals(3, table.forgotten());
        assertEquals(null, table.get("s4"));
    }

    /** The terminal's line says why the console is silent: listening first at start, or a game in play and whose. */
    @Test
    void theTerminalSaysWhyTheConsoleIsSilent() {
        ch.qos.logback.classic.Logger log = (ch.qos.logback.classic.Logger) org.slf4j.LoggerFactory.getLogger(MatchMode.class);
        ch.qos.logback.core.read.ListAppender<ch.qos.logback.classic.spi.ILoggingEvent> lines = new ch.qos.logback.core.read.ListAppender<>();
        lines.start();
        ch.qos.logback.classic.Level level = log.getLevel();
        log.setLevel(ch.qos.logback.classic.Level.INFO);
        log.addAppender(lines);
        try {
            mode.observe(3, "GameController at 10.0.0.2:3838");
            mode.observe(4, "GameController at 10.0.0.2:3838");
            clock.advance(MatchMode.PLAY_MEMORY_MS + 1);
            mode.refresh();
            mode.listenFirst(1_000);
            mode.refresh();
            assertEquals(List.of(
                    "match mode: console silent: a game in play (GameController at 10.0.0.2:3838)",
                    "match mode: console may send again",
                    "match mode: console silent: listening for a GameController before talking to robots"),
                    lines.list.stream().map(ch.qos.logback.classic.spi.ILoggingEvent::getFormattedMessage).toList());
        } finally {
            log.detachAppender(lines);
            log.setLevel(level);
        }
    }

    @Test
    void readyAndSetBlockToo_FinishedReleasesAndListenersHearIt() {
        List<Boolean> heard = new ArrayList<>();
        mode.addListener(heard::add);
        mode.observe(1, "gc");
        assertFalse(mode.mayConsoleSend());
        mode.observe(2, "gc");
        assertFalse(mode.mayConsoleSend());
        mode.hold("nao command");
        mode.observe(4, "gc");
        assertFalse(mode.mayConsoleSend(), "a claim of play holds for PLAY_MEMORY_MS");
        clock.advance(MatchMode.PLAY_MEMORY_MS + 1);
        assertTrue(mode.mayConsoleSend());
        assertEquals(List.of(false, true), heard);
        assertTrue(mode.heldBack().isEmpty(), "held-back list is cleared when they may resume");
    }

    @Test
    void anyPlayingSourceBlocksAndSilentSourcesExpire() {
        mode.observe(0, "ours");
        mode.observe(3, "other");
        assertFalse(mode.mayConsoleSend());
        clock.advance(MatchMode.STALE_MS + 1);
        mode.observe(0, "ours");
        assertTrue(mode.mayConsoleSend(), "a GameController not heard for 5 s no longer counts");
    }

    @Test
    void aForgedFinishedNeverReleasesWhileAnySourceSaidPlayingRecently() {
        mode.observe(3, "GameController at 10.0.0.2:3838");
        // the forger uses the GameController's own address: the latest state of that source is FINISHED
        mode.observe(4, "GameController at 10.0.0.2:3838");
        assertFalse(mode.mayConsoleSend());
        assertTrue(mode.play().contains("game was PLAYING"), mode.play());
        clock.advance(MatchMode.PLAY_MEMORY_MS / 2);
        mode.observe(3, "GameController at 10.0.0.2:3838");
        mode.observe(4, "other source at 10.0.0.66:40000");
        mode.observe(0, "GameController at 10.0.0.2:3838");
        clock.advance(MatchMode.PLAY_MEMORY_MS / 2 + 1);
        assertFalse(mode.mayConsoleSend(), "PLAYING heard 1 s ago");
        clock.advance(MatchMode.PLAY_MEMORY_MS / 2);
        assertTrue(mode.mayConsoleSend(), "no claim of play within PLAY_MEMORY_MS: released");
    }

    @Test
    void overrideIsExplicitAndLogged() {
        mode.observe(3, "gc");
        mode.setOverride(true, "referee allowed a config fix");
        assertTrue(mode.mayConsoleSend());
        assertTrue(mode.notice().startsWith("MATCH MODE OVERRIDDEN"), mode.notice());
        mode.setOverride(false, "done");
        assertFalse(mode.mayConsoleSend());
        assertEquals(2, mode.overrideLog().size());
        assertEquals("referee allowed a config fix", mode.overrideLog().get(0).reason());
        assertTrue(mode.overrideLog().get(0).on());
    }

    @Test
    void aConsoleStartingToListenStaysSilentForOneGameControllerInterval() {
        List<Boolean> heard = new ArrayList<>();
        mode.addListener(heard::add);
        mode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        assertFalse(mode.mayConsoleSend());
        assertTrue(mode.hold("debug option vision.ball"));
        assertTrue(mode.notice().contains("listening for a GameController"), mode.notice());
        clock.advance(MatchMode.LISTEN_FIRST_MS - 1);
        assertFalse(mode.mayConsoleSend());
        clock.advance(1);
        assertTrue(mode.mayConsoleSend(), "nothing heard in one interval: the console may talk");
        assertEquals(List.of(false, true), heard);
        assertEquals("", mode.notice());
    }

    /** What a one-shot command waits out before it sends (`options --off`): the listening, not play. */
    @Test
    void listeningFirstIsTheStartsWindowOnlyNotPlay() {
        assertFalse(mode.listeningFirst(), "not listening before listenFirst");
        mode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        assertTrue(mode.listeningFirst());
        clock.advance(300);
        mode.observe(3, "gc");
        assertFalse(mode.listeningFirst(), "play heard: held for play, nothing to wait out");
        assertFalse(mode.mayConsoleSend());
        MatchMode fresh = new MatchMode(clock);
        fresh.listenFirst(MatchMode.LISTEN_FIRST_MS);
        clock.advance(MatchMode.LISTEN_FIRST_MS);
        assertFalse(fresh.listeningFirst(), "the window is over");
        assertTrue(fresh.mayConsoleSend());
    }

    /**
     * Started during play on Wi-Fi that loses one GameController packet in two: PLAYING is heard
     * once a second, so the first one may come 1 s after the start; the console is still silent.
     */
    @Test
    void theFirstListenOutlastsTwoGameControllerIntervals() {
        assertTrue(MatchMode.LISTEN_FIRST_MS * 2 >= MatchMode.GAMECONTROLLER_INTERVAL_MS * 5,
                "at least 2.5 intervals: " + MatchMode.LISTEN_FIRST_MS);
        mode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        clock.advance(2 * MatchMode.GAMECONTROLLER_INTERVAL_MS); // one packet lost, the next just due
        assertFalse(mode.mayConsoleSend(), "a lossy GameController not heard yet: still listening");
        assertTrue(mode.play().startsWith("listening for a GameController before talking to robots ("
                + (MatchMode.LISTEN_FIRST_MS - 2 * MatchMode.GAMECONTROLLER_INTERVAL_MS) + " ms more"), mode.play());
        mode.observeBelieved(3, "GameController at 10.0.0.2:3838");
        clock.advance(MatchMode.LISTEN_FIRST_MS);
        assertFalse(mode.mayConsoleSend());
    }

    /** The wait ends as soon as the GameController it believes says play is off; robots and strangers do not end it. */
    @Test
    void aNonPlayStateFromTheBelievedGameControllerEndsTheFirstListenAtOnce() {
        List<String> ends = new ArrayList<>();
        mode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        mode.onListenEnd(ends::add);
        clock.advance(100);
        mode.observe(0, "robot 3"); // a robot that heard no GameController reports INITIAL
        mode.observe(4, "other source at 10.0.0.66:40000");
        assertFalse(mode.mayConsoleSend());
        assertEquals(List.of(), ends);
        mode.observeBelieved(0, "GameController at 10.0.0.2:3838");
        assertTrue(mode.mayConsoleSend());
        assertEquals(List.of("heard INITIAL (GameController at 10.0.0.2:3838): talking to robots"), ends);
        List<String> late = new ArrayList<>();
        mode.onListenEnd(late::add); // told at once, once
        mode.refresh();
        assertEquals(ends, late);
        assertEquals(1, ends.size());
    }

    @Test
    void theEndOfTheFirstListenSaysWhy() {
        List<String> ends = new ArrayList<>();
        mode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        mode.onListenEnd(ends::add);
        clock.advance(MatchMode.LISTEN_FIRST_MS);
        mode.refresh();
        assertEquals(List.of("no GameController heard in " + MatchMode.LISTEN_FIRST_MS + " ms: talking to robots"), ends);
        MatchMode fresh = new MatchMode(clock);
        fresh.listenFirst(MatchMode.LISTEN_FIRST_MS);
        fresh.onListenEnd(ends::add);
        fresh.observeBelieved(3, "GameController at 10.0.0.2:3838");
        assertEquals("a game in play (GameController at 10.0.0.2:3838): silent while it lasts", ends.get(1));
    }

    @Test
    void aPlayingHeardWhileListeningKeepsTheConsoleSilent() {
        mode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        clock.advance(300);
        mode.observe(3, "gc");
        clock.advance(MatchMode.LISTEN_FIRST_MS);
        assertFalse(mode.mayConsoleSend());
        assertTrue(mode.notice().contains("PLAYING"), mode.notice());
    }
}
