package touchline.game.hsl;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.game.ManualClock;
import touchline.game.Outcome;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.TeamColour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Rules the golden games do not reach: legality, the mercy rule, budgets, timeouts, undo. */
class HslGameTest {

    private ManualClock clock;
    private HslGame game;

    @BeforeEach
    void setUp() {
        clock = new ManualClock(0);
        game = new HslGame(HslRules.v7(Competition.SMALL_FOUNDATION), 5, HslGameGoldenTest.HOME, 14,
                HslGameGoldenTest.AWAY, clock);
    }

    private void ok(String command) {
        HslActionSyntax.Parsed p = new HslActionSyntax().parse(command);
        assertNull(p.error(), command);
        Outcome o = game.perform(p.action());
        assertTrue(o.applied(), command + ": " + o.message());
    }

    private void refused(String command) {
        GameControlData before = game.trueData();
        Outcome o = game.perform(new HslActionSyntax().parse(command).action());
        assertFalse(o.applied(), "should be illegal: " + command);
        assertTrue(o.message().startsWith("illegal now: "), o.message());
        assertEquals(before, game.trueData(), "a refused action changed the state");
    }

    private void secs(double s) {
        clock.advance((long) (s * 1000));
    }

    private void kickOffAndPlay(int team) {
        ok("kickoff " + team);
        ok("set");
        ok("play");
        secs(10);
    }

    @Test
    void competitionSetsTeamSizeAndTypeTheRestAreSubstitutes() {
        GameControlData d = game.controlData();
        assertEquals(4, d.playersPerTeam());
        assertEquals(0, d.competitionType());
        assertEquals(0, d.team(5).player(4).penalty());
        assertEquals(HslPenalty.SUBSTITUTE.neutral(), d.team(5).player(5).penalty());
        assertEquals(Competition.LARGE_ADVANCED, Competition.parse("large-advanced"));
        assertNull(Competition.parse("huge"));
    }

    @Test
    void clashingColoursAreRefused() {
        TeamColour[] redPurple = {TeamColour.RED, TeamColour.PURPLE};
        TeamColour[] purpleBlue = {TeamColour.PURPLE, TeamColour.BLUE};
        assertNotNull(HslGame.colourConflict(redPurple, new TeamColour[]{TeamColour.RED, TeamColour.BLUE}));
        assertNotNull(HslGame.colourConflict(redPurple, purpleBlue));
        assertThrows(IllegalArgumentException.class,
                () -> new HslGame(HslRules.v7(Competition.SMALL_FOUNDATION), 5, redPurple, 14, purpleBlue, clock));
    }

    @Test
    void onlyTheKickingTeamKicksOffAndSetPlaysNeedPlay() {
        refused("kickoff 14");
        refused("corner 5");
        refused("goal 5");
        refused("stop");
        ok("kickoff 5");
        refused("penaltykick 5");
    }

    @Test
    void readyEndsByItselfAfter45s() {
        ok("kickoff 5");
        secs(44.9);
        assertEquals(GameControlData.STATE_READY, game.controlData().state());
        secs(0.1);
        assertEquals(GameControlData.STATE_SET, game.controlData().state());
    }

    @Test
    void aGoalDuringTheHeldSetEndsTheHoldAndTheMercyRuleEndsTheGame() {
        ok("kickoff 5");
        ok("set");
        ok("play");
        assertEquals(GameControlData.STATE_SET, game.controlData().state(), "robots still see SET");
        assertEquals(GameControlData.STATE_PLAYING, game.trueData().state());
        ok("goal 5");
        assertEquals(GameControlData.STATE_READY, game.controlData().state(), "the hold ends with the goal");
        for (int goal = 2; goal <= 10; goal++) {
            ok("set");
            ok("play");
            ok("goal 5");
        }
        assertEquals(GameControlData.STATE_FINISHED, game.controlData().state(), "10:0 ends the game");
        assertEquals(10, game.controlData().team(5).score());
        assertFalse(game.controlData().firstHalf(), "no second half after the mercy rule");
        refused("secondhalf");
    }

    @Test
    void theBudgetCountsOnTheFieldOnlyAndAnEmptyBudgetZeroesTheScore() {
        ok("teammessage 5");
        assertEquals(12000, game.controlData().team(5).messageBudget(), "not counted in INITIAL");
        kickOffAndPlay(5);
        ok("goal 14");
        ok("teammessage 14 512");
        assertEquals(11999, game.controlData().team(14).messageBudget(), "512 bytes is legal");
        HslState s = game.snapshot();
        assertEquals(1, s.team(14).score());
        for (int i = 0; i < 11999; i++) {
            game.perform(new TeamMessage(14, 10));
        }
        assertEquals(0, game.controlData().team(14).messageBudget());
        assertEquals(1, game.controlData().team(14).score());
        ok("teammessage 14");
        assertEquals(0, game.controlData().team(14).score(), "a message beyond the budget");
        assertTrue(game.snapshot().team(14).illegalCommunication());
        ok("set");
        ok("play");
        ok("goal 14");
        assertEquals(0, game.controlData().team(14).score(), "later goals do not count");
    }

    @Test
    void teamMessagesAreNotUndone() {
        kickOffAndPlay(5);
        ok("teammessage 5");
        ok("stop");
        assertEquals("stop", game.undoList().get(0));
        assertTrue(game.undo().applied());
        assertFalse(game.controlData().stopped());
        assertEquals(11999, game.controlData().team(5).messageBudget(), "the message stays counted");
    }

    @Test
    void aTeamHasOneTimeoutAndARefereeTimeoutDuringPlayDropsTheBall() {
        ok("timeout 14");
        assertEquals(3, game.controlData().gamePhase());
        assertEquals(GameControlData.STATE_INITIAL, game.controlData().state());
        assertEquals(5, game.controlData().kickOffTeam(), "the other team kicks off");
        kickOffAndPlay(5);
        refused("timeout 5");
        ok("timeout referee");
        assertEquals(600, game.controlData().secondaryTime());
        assertEquals(GameControlData.DROP_BALL, game.controlData().kickOffTeam());
        refused("kickoff 5");
        ok("droppedball");
        assertEquals(GameControlData.STATE_READY, game.controlData().state());
        assertEquals(GameControlData.DROP_BALL, game.controlData().kickOffTeam());
        ok("set");
        refused("timeout 14");
    }

    @Test
    void aTimeoutStopsPenaltyTimersAndATimeoutInATimeoutAddsToIt() {
        kickOffAndPlay(5);
        ok("penalize 14 3 pushing");
        ok("unpenalize 14 3");
        secs(10);
        assertEquals(35, game.controlData().team(14).player(3).secsTillUnpenalised());
        ok("penaltykick 14");
        refused("timeout 5");
        ok("timeout referee");
        assertEquals(GameControlData.DROP_BALL, game.controlData().kickOffTeam(), "no kick-off was due");
        assertEquals(0, game.controlData().team(14).player(3).secsTillUnpenalised(), "timer stopped");
        assertEquals(HslPenalty.PUSHING.neutral(), game.controlData().team(14).player(3).penalty());
        secs(100);
        ok("timeout 5");
        assertEquals(800, game.controlData().secondaryTime(), "500 s left + 300 s");
        assertEquals(14, game.controlData().kickOffTeam());
        ok("unpenalize 14 3");
        assertEquals(45, game.controlData().team(14).player(3).secsTillUnpenalised(), "starts again in full");
    }

    @Test
    void motionInStopOnlyWhileStoppedAndMotionInSetOnlyInSet() {
        ok("kickoff 5");
        refused("penalize 5 1 motion_in_set");
        ok("set");
        ok("penalize 5 1 motion_in_set");
        ok("play");
        secs(10);
        refused("penalize 5 2 motion_in_stop");
        ok("stop");
        ok("penalize 5 2 motion_in_stop");
        assertEquals(0, game.controlData().team(5).player(2).secsTillUnpenalised(), "waits for the operator");
        ok("unpenalize 5 2");
        secs(30);
        assertEquals(45, game.controlData().team(5).player(2).secsTillUnpenalised(), "stands while stopped");
        refused("unpenalize 5 2");
        ok("unpenalize 5 2 force");
        assertEquals(0, game.controlData().team(5).player(2).penalty());
    }

    @Test
    void incrementalPenaltiesGrowBy10sPerEarlierOne() {
        kickOffAndPlay(5);
        ok("penalize 14 1 pushing");
        ok("penalize 14 2 ball_holding");
        ok("penalize 14 3 local_game_stuck");
        ok("unpenalize 14 1");
        ok("unpenalize 14 2");
        ok("unpenalize 14 3");
        GameControlData d = game.controlData();
        assertEquals(45, d.team(14).player(1).secsTillUnpenalised());
        assertEquals(55, d.team(14).player(2).secsTillUnpenalised());
        assertEquals(45, d.team(14).player(3).secsTillUnpenalised(), "not incremental");
    }

    @Test
    void pickUpInInitialHasNoTimeAndSendOffsOutlastTheHalf() {
        ok("penalize 5 3 pick_up");
        assertEquals(HslPenalty.PICK_UP.neutral(), game.controlData().team(5).player(3).penalty());
        assertEquals(0, game.controlData().team(5).player(3).secsTillUnpenalised());
        ok("unpenalize 5 3");
        assertEquals(0, game.controlData().team(5).player(3).penalty(), "served at once");
        kickOffAndPlay(5);
        ok("sendoff 5 1");
        assertEquals(0, game.snapshot().team(5).goalkeeper(), "the goalkeeper was sent off");
        refused("unpenalize 5 1 force");
        ok("penalize 14 2 pushing");
        ok("finish");
        refused("additionalminute");
        ok("secondhalf");
        GameControlData d = game.controlData();
        assertEquals(14, d.teams().get(0).teamNumber(), "sides swapped");
        assertEquals(HslPenalty.SENT_OFF.neutral(), d.team(5).player(1).penalty());
        assertEquals(0, d.team(14).player(2).penalty(), "other penalties end with the half");
        assertEquals(14, d.kickOffTeam());
    }

    @Test
    void version19HasNoCautionsAndStopsTheClockWhileStopped() {
        game = new HslGame(HslRules.v6(Competition.MIDDLE_ADVANCED), 5, HslGameGoldenTest.HOME, 14,
                HslGameGoldenTest.AWAY, clock);
        kickOffAndPlay(5);
        refused("caution 5 2");
        refused("penalize 5 2 motion_in_stop");
        ok("stop");
        int before = game.controlData().secsRemaining();
        secs(20);
        assertEquals(before, game.controlData().secsRemaining());
        ok("resume");
        secs(20);
        assertEquals(before - 20, game.controlData().secsRemaining());
    }

    @Test
    void additionalMinuteNeedsAMinutePlayedAndNotPlaying() {
        refused("additionalminute");
        kickOffAndPlay(5);
        secs(51);
        refused("additionalminute");
        ok("goal 5");
        int before = game.controlData().secsRemaining();
        ok("additionalminute");
        assertEquals(before + 60, game.controlData().secsRemaining());
        assertEquals(12600, game.controlData().team(14).messageBudget());
    }

    @Test
    void aPenaltyShootoutAlternatesShotsAndCountsGoalsInSingleShots() {
        kickOffAndPlay(5);
        ok("finish");
        refused("penaltyshootout 5");
        ok("secondhalf");
        kickOffAndPlay(14);
        ok("finish");
        ok("penaltyshootout 14");
        GameControlData d = game.controlData();
        assertEquals(1, d.gamePhase());
        assertEquals(GameControlData.STATE_INITIAL, d.state());
        assertEquals(14, d.kickOffTeam());
        assertEquals(60, d.secsRemaining());
        assertEquals(HslPenalty.SUBSTITUTE.neutral(), d.team(14).player(1).penalty(), "everybody off");
        assertEquals(0, game.snapshot().team(5).goalkeeper());
        ok("shot");
        refused("play");
        ok("shooter 14 3");
        ok("shooter 5 1 goalkeeper");
        assertEquals(1, game.snapshot().team(5).goalkeeper());
        assertEquals(0, game.controlData().team(14).player(3).penalty());
        ok("play");
        assertEquals(GameControlData.STATE_SET, game.controlData().state(), "robots see SET for 10 s");
        secs(5);
        ok("goal 14");
        d = game.controlData();
        assertEquals(GameControlData.STATE_FINISHED, d.state());
        assertEquals(1, d.team(14).score());
        assertEquals(1, d.team(14).penaltyShot());
        assertEquals(0b1, d.team(14).singleShots());
        assertEquals(5, d.kickOffTeam(), "the other team shoots next");
        refused("goal 5");
        ok("shot");
        ok("play");
        secs(60);
        d = game.controlData();
        assertEquals(GameControlData.STATE_FINISHED, d.state(), "the shot's 60 s ran out");
        assertEquals(0, d.team(5).singleShots());
        assertEquals(14, d.kickOffTeam());
        ok("shot");
        ok("play");
        ok("missed");
        ok("teammessage 14");
        assertEquals(12000, game.controlData().team(14).messageBudget(), "not counted in a shoot-out");
        assertEquals(2, game.controlData().team(14).penaltyShot());
    }

    @Test
    void extraTimeIsTwoShortHalvesInTheFirstHalfsSidesWith6000MoreMessages() {
        kickOffAndPlay(5);
        ok("finish");
        refused("extratime");
        ok("secondhalf");
        kickOffAndPlay(14);
        ok("penalize 14 2 pushing");
        ok("finish");
        ok("extratime");
        GameControlData d = game.controlData();
        assertEquals(2, d.gamePhase());
        assertEquals(GameControlData.STATE_INITIAL, d.state());
        assertTrue(d.firstHalf(), "7.x: firstHalf in the first half of extra time");
        assertEquals(5, d.teams().get(0).teamNumber(), "sides of the first half");
        assertEquals(5, d.kickOffTeam());
        assertEquals(300, d.secsRemaining());
        assertEquals(18000, d.team(14).messageBudget());
        assertEquals(0, d.team(14).player(2).penalty());
        kickOffAndPlay(5);
        ok("finish");
        ok("secondhalf");
        assertEquals(300, game.controlData().secsRemaining());
        assertEquals(14, game.controlData().teams().get(0).teamNumber());
        kickOffAndPlay(14);
        ok("finish");
        ok("penaltyshootout 5");
    }

    @Test
    void syntaxErrorsAreValues() {
        HslActionSyntax syntax = new HslActionSyntax();
        assertEquals("unknown command 'fly' (see --help)", syntax.parse("fly away").error());
        assertEquals("unknown call 'tripping'", syntax.parse("penalize 5 2 tripping").error());
        assertEquals("missing argument for 'goal'", syntax.parse("goal").error());
        assertEquals("not a number in 'goal five'", syntax.parse("goal five").error());
        assertEquals("usage: unpenalize TEAM PLAYER [force]", syntax.parse("unpenalize 5 2 now").error());
    }
}
