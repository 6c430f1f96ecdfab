package touchline.game.hsl;

import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.Goal;
import touchline.game.LeagueAction;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.game.Outcome;
import touchline.game.RefereedGame;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.protocol.gamecontroller.GameControlData;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The actions both leagues share are one class each: the same action under HL and HSL rules, and where they differ. */
class SharedActionsTest {

    private final ManualClock clock = new ManualClock(0);

    /** An HL game with teams 5 and 14 and how it gets to PLAYING (again). */
    private final RefereedGame hl = new Game(LeagueParams.hlSimulationKidSize(), 5, 0, 14, 1, clock);
    private final List<LeagueAction<?>> hlToPlaying = List.of(new ToSet(), new ToPlaying());

    private final RefereedGame hsl = new HslGame(HslRules.v7(Competition.SMALL_FOUNDATION), 5, HslGameGoldenTest.HOME,
            14, HslGameGoldenTest.AWAY, clock);
    private final List<LeagueAction<?>> hslToPlaying = List.of(new WaitForSetPlay(), new FreeSetPlay());

    private static void ok(RefereedGame game, LeagueAction<?> action) {
        Outcome o = game.perform(action);
        assertTrue(o.applied(), action.describe() + ": " + o.message());
    }

    private static void goals(RefereedGame game, List<LeagueAction<?>> toPlaying, int goals) {
        for (int goal = 1; goal <= goals; goal++) {
            toPlaying.forEach(a -> ok(game, a));
            ok(game, new Goal(5));
        }
    }

    @Test
    void oneGoalIsLegalAndLandsAlikeInBothLeagues() {
        Goal goal = new Goal(5);
        assertFalse(hl.perform(goal).applied(), "HL: no goal before PLAYING");
        assertFalse(hsl.perform(goal).applied(), "HSL: no goal before PLAYING");
        ok(hl, new ToReady());
        ok(hsl, new HslStartSetPlay(5, SetPlay.KICK_OFF));

        goals(hl, hlToPlaying, 1);
        goals(hsl, hslToPlaying, 1);

        for (RefereedGame game : List.of(hl, hsl)) {
            GameControlData d = game.trueData();
            assertEquals(1, d.team(5).score());
            assertEquals(GameControlData.STATE_READY, d.state(), "back to READY after a goal");
            assertEquals(14, d.kickOffTeam(), "the other team kicks off");
        }
    }

    @Test
    void theMercyRuleIsTheLeaguesTenGoalsEndTheHslGameOnly() {
        ok(hl, new ToReady());
        ok(hsl, new HslStartSetPlay(5, SetPlay.KICK_OFF));

        goals(hl, hlToPlaying, 10);
        goals(hsl, hslToPlaying, 10);

        assertEquals(10, hl.trueData().team(5).score());
        assertEquals(GameControlData.STATE_READY, hl.trueData().state(), "HL has no mercy rule: play goes on");
        assertEquals(10, hsl.trueData().team(5).score());
        assertEquals(GameControlData.STATE_FINISHED, hsl.trueData().state(), "HSL: 10:0 ends the game");
        assertFalse(hsl.trueData().firstHalf(), "no second half after the mercy rule");
    }

    @Test
    void eachGameRefusesTheOtherLeaguesOwnActions() {
        Outcome o = hl.perform(new HslStartSetPlay(5, SetPlay.KICK_OFF));
        assertFalse(o.applied());
        assertEquals("kick off 5 is not an action of this game's rules", o.message());
        assertFalse(hsl.perform(new ToReady()).applied());
    }
}
