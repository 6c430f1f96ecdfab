package touchline.game.hsl;

import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.Goal;
import touchline.game.LeagueAction;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.game.Outcome;
import touchline.game.RefereedGame;
import touchline.game.StartPenaltyShootout;
import touchline.game.ToFinished;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.RobotInfo;

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

    @Test
    void oneShootOutStartsWhereBothLeaguesAgreeTheFirstShooterIsAParameterThePlayersTheLeagues() {
        StartPenaltyShootout gameKickOff = new StartPenaltyShootout();
        for (LeagueAction<?> a : List.of(new ToReady(), new ToSet(), new ToPlaying(), new ToFinished(),
                new ToReady(), new ToSet(), new ToPlaying())) {
            ok(hl, a);
        }
        for (LeagueAction<?> a : List.of(new HslStartSetPlay(5, SetPlay.KICK_OFF), new WaitForSetPlay(),
                new FreeSetPlay(), new FinishHalf(), new SwitchHalf(), new HslStartSetPlay(14, SetPlay.KICK_OFF),
                new WaitForSetPlay(), new FreeSetPlay())) {
            ok(hsl, a);
        }
        assertFalse(hl.perform(gameKickOff).applied(), "HL: not before the second half finished");
        assertFalse(hsl.perform(gameKickOff).applied(), "HSL: not before the second half finished");
        ok(hl, new ToFinished());
        ok(hsl, new FinishHalf());

        ok(hl, gameKickOff);
        ok(hsl, gameKickOff);
        assertFalse(hl.perform(gameKickOff).applied(), "HL: one shoot-out");
        assertFalse(hsl.perform(gameKickOff).applied(), "HSL: one shoot-out");

        GameControlData l = hl.trueData();
        GameControlData h = hsl.trueData();
        for (GameControlData d : List.of(l, h)) {
            assertEquals(GameControlData.STATE_INITIAL, d.state());
            assertEquals(5, d.kickOffTeam(), "the team that kicked off the game shoots first");
        }
        assertEquals(1, l.secondaryState(), "HL: secondary state PENALTYSHOOT");
        assertEquals(1, h.gamePhase(), "HSL: game phase PENALTY_SHOOT_OUT");
        RobotInfo hlPlayer = l.team(5).players().get(0);
        RobotInfo hslPlayer = h.team(5).players().get(0);
        assertEquals(0, hlPlayer.penalty(), "HL: the players stay on");
        assertEquals(HslPenalty.SUBSTITUTE.neutral(), hslPlayer.penalty(), "HSL: off until the team selects its shooter");
        assertEquals(List.of("penaltyshootout", "finish"), hl.undoList().subList(0, 2));
    }

    @Test
    void theRefereeNamesTheFirstShooter() {
        for (LeagueAction<?> a : List.of(new HslStartSetPlay(5, SetPlay.KICK_OFF), new FinishHalf(), new SwitchHalf(),
                new HslStartSetPlay(14, SetPlay.KICK_OFF), new FinishHalf())) {
            ok(hsl, a);
        }
        assertFalse(hsl.perform(new StartPenaltyShootout(99)).applied(), "not a team of the game");
        ok(hsl, new StartPenaltyShootout(14));
        assertEquals(14, hsl.trueData().kickOffTeam());
        assertEquals("penalty shoot-out, 14 first", hsl.undoList().get(0), "as the HSL undo list always named it");
    }
}
