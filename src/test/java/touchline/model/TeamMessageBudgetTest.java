package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.TeamInfo;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The budget guard on a manual clock, with the official HSL v20 datagrams as the GameController. */
class TeamMessageBudgetTest {

    private static final int TEAM = 5;
    private final long[] now = {1_000_000_000L};
    private final RuleProfile hsl = profile("hsl-2026");

    private static RuleProfile profile(String name) {
        try {
            return RuleProfile.named(name);
        } catch (RuleProfileException e) {
            throw new AssertionError(e.getMessage());
        }
    }

    private static byte[] golden(String step) throws IOException {
        try (InputStream in = TeamMessageBudgetTest.class.getResourceAsStream("/golden/gamecontroller/hsl20/" + step)) {
            assertNotNull(in, step);
            return in.readAllBytes();
        }
    }

    private Envelope gc(byte[] raw) {
        return new Envelope(now[0], Direction.IN, Channel.GAMECONTROLLER, new InetSocketAddress("127.0.0.1", 3838),
                Envelope.NO_ROBOT, "gc.hsl20", null, raw, null);
    }

    private Envelope message(int robot, int bytes) {
        return new Envelope(now[0], Direction.IN, Channel.TEAM_MESSAGE, new InetSocketAddress("127.0.0.1", 40000 + robot),
                Envelope.NO_ROBOT, "team.message", null, new byte[bytes], null);
    }

    /** Sends {@code count} messages spread over {@code seconds}, round robin over three robots. */
    private void send(TeamMessageBudget budget, int count, int seconds) {
        long step = seconds * 1_000_000L / count;
        for (int i = 0; i < count; i++) {
            budget.accept(message(1 + i % 3, 40));
            now[0] += step;
        }
    }

    @Test
    void withoutAGameControllerMessagesAreHeardButNotCounted() throws IOException {
        TeamMessageBudget budget = new TeamMessageBudget(() -> now[0], hsl, TEAM);
        send(budget, 30, 10);
        TeamMessageBudget.Snapshot before = budget.snapshot();
        assertEquals(0, before.used(), "the state is not known: INITIAL does not count");
        assertEquals(30, before.notCounted());
        assertFalse(before.gameControllerHeard());
        assertEquals(12_000, before.left());
        assertTrue(before.describe().contains("30 heard, not counted: no GameController heard yet"), before.describe());
        assertEquals("0 used · 12000 left · no GameController: not counting", before.brief());
        assertEquals(3, before.senders().size(), "the senders are listed all the same");

        budget.accept(gc(golden("01-kickoff-team5-ready.bin")));
        send(budget, 120, 60);
        TeamMessageBudget.Snapshot s = budget.snapshot();
        assertEquals(120, s.used());
        assertTrue(s.gameControllerHeard());
        // the last minute in 5 s buckets: the oldest bucket has just left the window
        assertTrue(s.perMinute() >= 110 && s.perMinute() <= 120, "rate " + s.perMinute());
        assertEquals(TeamMessageBudget.Verdict.ON_TRACK, s.verdict(), s.describe());
        assertTrue(s.brief().startsWith("120 used · " + s.left() + " left · lasts"), s.brief());
    }

    @Test
    void theGameControllersOwnCountWinsAndTheForecastWarnsBeforeTheBudgetRunsOut() throws IOException {
        byte[] playing = golden("07-playing-after-delay.bin");
        GameControlData data = new KnownGameStateFormats().recognise(playing).value().data();
        TeamInfo ours = data.teams().stream().filter(t -> t.teamNumber() == TEAM).findFirst().orElseThrow();
        TeamMessageBudget budget = new TeamMessageBudget(() -> now[0], hsl, TEAM);
        budget.accept(gc(playing));
        send(budget, 60, 60); // one a second: lasts
        TeamMessageBudget.Snapshot calm = budget.snapshot();
        assertTrue(calm.leftFromGc());
        assertEquals(ours.messageBudget(), calm.left());
        long gameLeft = data.secsRemaining() + (data.firstHalf() ? 600 : 0);
        assertEquals(gameLeft, calm.secondsLeftInGame());
        assertEquals(TeamMessageBudget.Verdict.ON_TRACK, calm.verdict(), calm.describe());

        // a team that talks 40 times a second empties what is left long before the end
        send(budget, 2400, 60);
        TeamMessageBudget.Snapshot hot = budget.snapshot();
        assertTrue(hot.secondsToEmpty() < hot.secondsLeftInGame(), hot.describe());
        assertEquals(TeamMessageBudget.Verdict.RUNS_OUT_BEFORE_THE_END, hot.verdict());
        assertTrue(hot.describe().contains("WARNING"), hot.describe());
    }

    @Test
    void theConsolesOwnGameControllerIsHeardToo() throws IOException {
        TeamMessageBudget budget = new TeamMessageBudget(() -> now[0], hsl, TEAM);
        Envelope in = gc(golden("07-playing-after-delay.bin"));
        budget.accept(new Envelope(in.timeMicros(), Direction.OUT, in.channel(), in.peer(), in.robotId(), in.kind(),
                null, in.raw(), null));
        send(budget, 10, 10);
        assertTrue(budget.snapshot().leftFromGc(), "the tab's own GameController gives the budget");
    }

    @Test
    void messagesOutsideReadySetPlayingDoNotCount() throws IOException {
        TeamMessageBudget budget = new TeamMessageBudget(() -> now[0], hsl, TEAM);
        budget.accept(gc(golden("00-initial.bin")));
        send(budget, 30, 10);
        assertEquals(0, budget.snapshot().used(), "INITIAL: the GameController does not count them either");
        budget.accept(gc(golden("01-kickoff-team5-ready.bin")));
        send(budget, 30, 10);
        assertEquals(30, budget.snapshot().used());
    }

    @Test
    void aMessageOverTheSizeLimitIsFlaggedAtOnceWithItsSender() {
        TeamMessageBudget budget = new TeamMessageBudget(() -> now[0], hsl, TEAM);
        budget.accept(message(2, 512));
        assertEquals(0, budget.snapshot().oversize(), "512 bytes is still legal");
        budget.accept(message(3, 600));
        TeamMessageBudget.Snapshot s = budget.snapshot();
        assertEquals(1, s.oversize());
        assertTrue(s.lastOversize().contains("127.0.0.1:40003") && s.lastOversize().contains("600 bytes"), s.lastOversize());
        assertTrue(s.describe().contains("over 512 bytes"), s.describe());
    }

    @Test
    void aProfileWithoutABudgetSaysSoInsteadOfInventingOne() {
        TeamMessageBudget lab = new TeamMessageBudget(() -> now[0], profile("lab"), TEAM);
        send(lab, 10, 10);
        assertEquals(TeamMessageBudget.Verdict.NO_LIMIT, lab.snapshot().verdict());
        TeamMessageBudget spl = new TeamMessageBudget(() -> now[0], profile("spl-2025"), TEAM);
        send(spl, 10, 10);
        assertEquals(TeamMessageBudget.Verdict.LIMIT_NOT_KNOWN, spl.snapshot().verdict());
        assertTrue(spl.snapshot().describe().contains("not known"), spl.snapshot().describe());
    }

    @Test
    void theRateForgetsMessagesOlderThanAMinute() throws IOException {
        TeamMessageBudget budget = new TeamMessageBudget(() -> now[0], hsl, TEAM);
        budget.accept(gc(golden("07-playing-after-delay.bin")));
        send(budget, 60, 30);
        now[0] += 120_000_000L;
        TeamMessageBudget.Snapshot s = budget.snapshot();
        assertEquals(0, s.perMinute(), 0.001);
        assertEquals(60, s.used());
        assertEquals(TeamMessageBudget.Verdict.WAITING_FOR_MESSAGES, s.verdict());
    }
}
