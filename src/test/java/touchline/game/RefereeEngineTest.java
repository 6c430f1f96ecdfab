package touchline.game;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The one engine with a league of its own: the engine's part (legality, undo, listeners) apart from any rules. */
class RefereeEngineTest {

    /** A league whose state is a score and a count of seconds time has run. */
    private static final class Counting implements League<int[]> {
        final List<String> calls = new ArrayList<>();

        @Override
        public int[] copy(int[] s) {
            return s.clone();
        }

        @Override
        public boolean runTime(int[] s, long nowMs) {
            calls.add("time " + nowMs);
            s[1] = (int) (nowMs / 1000);
            return false;
        }

        @Override
        public void restored(int[] s, long nowMs) {
            calls.add("restored " + nowMs);
        }

        @Override
        public String describe(int[] s, long nowMs) {
            return "score " + s[0];
        }
    }

    private record Score(int max, boolean undoable) implements LeagueAction<int[]> {
        @Override
        public boolean isLegal(int[] s) {
            return s[0] < max;
        }

        @Override
        public void apply(int[] s, long nowMs) {
            s[0]++;
        }

        @Override
        public String describe() {
            return "score";
        }
    }

    @Test
    void timeRunsBeforeTheCheckRefusalsKeepNothingAndUndoGoesBackThroughTheLeague() {
        ManualClock clock = new ManualClock(0);
        Counting league = new Counting();
        RefereeEngine<int[]> engine = new RefereeEngine<>(league, new int[2], clock);
        int[] changes = {0};
        engine.addListener(() -> changes[0]++);
        clock.set(2000);
        assertTrue(engine.perform(new Score(1, true)).applied());
        assertEquals(List.of("time 2000"), league.calls, "time ran before the check");
        Outcome refused = engine.perform(new Score(1, true));
        assertFalse(refused.applied());
        assertEquals("illegal now: score (score 1)", refused.message());
        assertTrue(engine.perform(new Score(5, false)).applied());
        assertEquals(List.of("score"), engine.undoList(), "a change of the network's is not on the undo list");
        assertEquals(2, changes[0], "listeners hear changes, not refusals");
        clock.set(3000);
        assertEquals("undid score", engine.undo().message());
        assertEquals("restored 3000", league.calls.get(league.calls.size() - 1));
        assertEquals(0, (int) engine.read((s, now) -> s[0]));
        assertEquals("nothing to undo", engine.undo().message());
    }
}
