package touchline.game;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.protocol.gamecontroller.GameControlData;

import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Legality and effect of every action, against a clock the test moves. */
class GameTest {

    private ManualClock clock;
    private Game game;

    @BeforeEach
    void setUp() {
        clock = new ManualClock(1_000_000);
        game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock);
    }

    private void ok(LeagueAction<? super GameState> a) {
        Outcome o = game.perform(a);
        assertTrue(o.applied(), o.message());
    }

    private void refused(LeagueAction<? super GameState> a) {
        game.advance(); // perform() lets time-driven changes happen first
        GameState before = game.snapshot();
        Outcome o = game.perform(a);
        assertFalse(o.applied(), "should be illegal: " + a.describe());
        assertEquals(before.toControlData(clock.millis()), game.controlData(), "a refused action changed the state");
    }

    private void secs(int s) {
        clock.advance(s * 1000L);
    }

    private GameControlData wire() {
        return game.controlData();
    }

    private void kickOff() {
        ok(new ToReady());
        ok(new ToSet());
        ok(new ToPlaying());
    }

    @Test
    void initialStateHasSubstitutesGoalkeeperAndKickOffForTeamA() {
        GameState s = game.snapshot();
        assertEquals(PlayState.INITIAL, s.state());
        assertEquals(13, s.kickOffTeam());
        assertTrue(s.team(13).player(1).goalkeeper());
        assertEquals(Penalty.NONE, s.team(7).player(4).penalty());
        assertEquals(Penalty.SUBSTITUTE, s.team(7).player(5).penalty());
        assertEquals(600, wire().secsRemaining());
        assertEquals(0xFFFF, wire().dropInTime());
    }

    @Test
    void stateChangesFollowInitialReadySetPlayingFinished() {
        refused(new ToSet());
        refused(new ToPlaying());
        refused(new ToFinished());
        ok(new ToReady());
        refused(new ToReady());
        refused(new ToPlaying());
        ok(new ToSet());
        refused(new ToSet());
        ok(new ToPlaying());
        refused(new ToPlaying());
        ok(new ToFinished());
        assertEquals(PlayState.FINISHED.code(), wire().state());
    }

    @Test
    void halfClockRunsOnlyAfterTheFirstKickOffAndNotInFinished() {
        ok(new ToReady());
        secs(10);
        assertEquals(600, wire().secsRemaining());
        assertEquals(35, wire().secondaryTime());
        secs(40);
        assertEquals(0, wire().secondaryTime(), "READY countdown does not go below zero");
        ok(new ToSet());
        ok(new ToPlaying());
        assertEquals(10, wire().secondaryTime(), "kick-off block");
        secs(4);
        assertEquals(596, wire().secsRemaining());
        assertEquals(6, wire().secondaryTime());
        secs(20);
        assertEquals(0, wire().secondaryTime());
        ok(new Goal(13));
        secs(5);
        assertEquals(571, wire().secsRemaining(), "clock keeps running in READY after a goal");
        ok(new ToFinished());
        GameState s = game.snapshot();
        assertFalse(s.isClockRunning());
    }

    @Test
    void goalScoresAndGivesKickOffToTheOtherTeam() {
        refused(new Goal(13));
        kickOff();
        refused(new Goal(99));
        ok(new Goal(7));
        GameControlData d = wire();
        assertEquals(1, d.team(7).score());
        assertEquals(0, d.team(13).score());
        assertEquals(13, d.kickOffTeam());
        assertEquals(PlayState.READY.code(), d.state());
        assertEquals(45, d.secondaryTime());
    }

    @Test
    void kickOffTeamCanBeChosenOnlyBeforeTheGameStarts() {
        refused(new SetKickOff(13));
        refused(new SetKickOff(99));
        ok(new SetKickOff(7));
        assertEquals(7, wire().kickOffTeam());
        kickOff();
        refused(new SetKickOff(13));
        ok(new ToFinished());
        game.advance();
        assertEquals(13, wire().kickOffTeam(), "the other team kicks off the second half");
    }

    @Test
    void droppedBallHasNoKickingTeamAndNoBlock() {
        refused(new DropBall());
        kickOff();
        ok(new DropBall());
        assertEquals(GameControlData.DROP_BALL, wire().kickOffTeam());
        assertEquals(PlayState.READY.code(), wire().state());
        ok(new ToSet());
        ok(new ToPlaying());
        assertEquals(0, wire().secondaryTime());
        ok(new ToFinished());
        refused(new DropBall());
    }

    @Test
    void timeoutStopsPlayCountsDownAndIsLimited() {
        kickOff();
        refused(new Timeout(13));
        ok(new Goal(13));
        secs(3);
        int remaining = wire().secsRemaining();
        ok(new Timeout(7));
        GameControlData d = wire();
        assertEquals(PlayState.INITIAL.code(), d.state());
        assertEquals(SecondaryState.TIMEOUT.code(), d.secondaryState());
        assertEquals(120, d.secondaryTime());
        secs(30);
        assertEquals(90, wire().secondaryTime());
        assertEquals(remaining, wire().secsRemaining(), "the clock stands still in a timeout");
        refused(new Timeout(13));
        ok(new ToReady());
        assertEquals(SecondaryState.NORMAL.code(), wire().secondaryState());
        refused(new Timeout(7));
        ok(new Timeout(13));
    }

    @Test
    void setPlayStopsTheClockAndWalksThroughItsSubModes() {
        refused(new StartSetPlay(13, SecondaryState.CORNER_KICK));
        kickOff();
        refused(new StartSetPlay(13, SecondaryState.TIMEOUT));
        refused(new SetPlayStep(SetPlayStep.Step.READY));
        refused(new SetPlayStep(SetPlayStep.Step.ABORT));
        secs(20);
        ok(new StartSetPlay(7, SecondaryState.THROW_IN));
        refused(new StartSetPlay(13, SecondaryState.GOAL_KICK));
        refused(new SetPlayStep(SetPlayStep.Step.PREPARE));
        refused(new SetPlayStep(SetPlayStep.Step.EXECUTE));
        GameControlData d = wire();
        assertEquals(9, d.secondaryState());
        assertEquals(7, d.setPlayTeam());
        assertEquals(0, d.setPlayMode());
        int stopped = d.secsRemaining();
        ok(new SetPlayStep(SetPlayStep.Step.READY));
        assertEquals(15, wire().secondaryTime());
        secs(5);
        assertEquals(10, wire().secondaryTime());
        assertEquals(stopped, wire().secsRemaining());
        ok(new SetPlayStep(SetPlayStep.Step.PREPARE));
        assertEquals(2, wire().setPlayMode());
        assertEquals(0, wire().secondaryTime());
        ok(new SetPlayStep(SetPlayStep.Step.EXECUTE));
        assertEquals(0, wire().secondaryState());
        assertEquals(0, wire().setPlayTeam());
        assertEquals(10, wire().secondaryTime());
        secs(3);
        assertEquals(stopped - 3, wire().secsRemaining());
        ok(new StartSetPlay(13, SecondaryState.PENALTYKICK));
        ok(new SetPlayStep(SetPlayStep.Step.ABORT));
        assertEquals(0, wire().secondaryTime());
        assertEquals(0, wire().secondaryState());
    }

    @Test
    void timedPenaltyCountsDownAndEndsByItself() {
        kickOff();
        ok(new Penalize(7, 2, Penalty.PHYSICAL_CONTACT));
        refused(new Penalize(7, 2, Penalty.SERVICE));
        refused(new Penalize(7, 5, Penalty.SERVICE));
        refused(new Penalize(7, 12, Penalty.SERVICE));
        refused(new Penalize(7, 1, Penalty.SUBSTITUTE));
        assertEquals(31, wire().team(7).player(2).penalty());
        assertEquals(30, wire().team(7).player(2).secsTillUnpenalised());
        secs(12);
        assertEquals(18, wire().team(7).player(2).secsTillUnpenalised());
        secs(18);
        assertTrue(game.advance());
        assertEquals(0, wire().team(7).player(2).penalty());
        refused(new Unpenalize(7, 2));
    }

    @Test
    void manualPenaltyLastsUntilLifted() {
        ok(new Penalize(13, 3, Penalty.MANUAL));
        secs(100);
        game.advance();
        assertEquals(15, wire().team(13).player(3).penalty());
        assertEquals(0, wire().team(13).player(3).secsTillUnpenalised());
        ok(new Unpenalize(13, 3));
        assertEquals(0, wire().team(13).player(3).penalty());
        refused(new Unpenalize(13, 5));
    }

    @Test
    void cardsAndWarningsAreCounted() {
        ok(new Card(7, 3, Card.Kind.YELLOW));
        ok(new Card(7, 3, Card.Kind.YELLOW));
        ok(new Card(7, 3, Card.Kind.RED));
        ok(new Card(13, 1, Card.Kind.WARNING));
        refused(new Card(7, 0, Card.Kind.RED));
        refused(new Card(99, 1, Card.Kind.RED));
        assertEquals(2, wire().team(7).player(3).yellowCards());
        assertEquals(1, wire().team(7).player(3).redCards());
        assertEquals(1, wire().team(13).player(1).warnings());
        assertEquals(0, wire().team(13).player(1).penalty(), "a card sets no penalty");
    }

    @Test
    void substituteTakesOverPenaltyAndGoalkeeperRole() {
        kickOff();
        ok(new Penalize(13, 1, Penalty.PICKUP_OR_INCAPABLE));
        secs(5);
        refused(new Substitute(13, 1, 2));
        refused(new Substitute(13, 5, 6));
        ok(new Substitute(13, 1, 5));
        GameControlData d = wire();
        assertEquals(14, d.team(13).player(1).penalty());
        assertFalse(d.team(13).player(1).goalkeeper());
        assertEquals(34, d.team(13).player(5).penalty());
        assertEquals(25, d.team(13).player(5).secsTillUnpenalised());
        assertTrue(d.team(13).player(5).goalkeeper());
    }

    @Test
    void goalkeeperRoleMoves() {
        refused(new SetGoalkeeper(7, 1));
        refused(new SetGoalkeeper(7, 6));
        ok(new SetGoalkeeper(7, 3));
        assertFalse(wire().team(7).player(1).goalkeeper());
        assertTrue(wire().team(7).player(3).goalkeeper());
    }

    @Test
    void undoRevertsTheLastActionsInOrder() {
        assertFalse(game.undo().applied());
        kickOff();
        ok(new Goal(13));
        ok(new Card(7, 2, Card.Kind.YELLOW));
        assertEquals(java.util.List.of("card 7 2 yellow", "goal 13", "play", "set", "ready"), game.undoList());
        assertTrue(game.undo().applied());
        assertEquals(0, wire().team(7).player(2).yellowCards());
        assertTrue(game.undo().applied());
        assertEquals(0, wire().team(13).score());
        assertEquals(PlayState.PLAYING.code(), wire().state());
        assertEquals(13, wire().kickOffTeam());
    }

    @Test
    void halfTimeSwitchSwapsTeamsAndKeepsCardsButNotPenalties() {
        kickOff();
        ok(new Goal(13));
        ok(new Card(7, 3, Card.Kind.YELLOW));
        ok(new Penalize(7, 2, Penalty.SERVICE));
        ok(new ToFinished());
        assertEquals(4, wire().state());
        assertTrue(wire().firstHalf(), "FINISHED of the first half is published before the switch");
        secs(1);
        assertTrue(game.advance());
        GameControlData d = wire();
        assertEquals(0, d.state());
        assertFalse(d.firstHalf());
        assertEquals(7, d.teams().get(0).teamNumber());
        assertEquals(13, d.teams().get(1).teamNumber());
        assertEquals(1, d.team(13).score());
        assertEquals(1, d.team(7).player(3).yellowCards());
        assertEquals(0, d.team(7).player(2).penalty());
        assertEquals(600, d.secsRemaining());
        assertEquals(7, d.kickOffTeam());
        secs(5);
        assertEquals(-5, wire().secondaryTime(), "half-time pause 0 s counts below zero");
        kickOff();
        ok(new ToFinished());
        assertFalse(game.advance(), "no third half");
        assertEquals(4, wire().state());
    }

    @Test
    void listenersHearActionsUndoAndTimeDrivenChanges() {
        AtomicInteger changes = new AtomicInteger();
        game.addListener(changes::incrementAndGet);
        ok(new ToReady());
        game.perform(new ToPlaying()); // refused: no notification
        assertEquals(1, changes.get());
        game.undo();
        assertEquals(2, changes.get());
        ok(new Penalize(7, 1, Penalty.SERVICE));
        assertFalse(game.advance());
        secs(30);
        assertTrue(game.advance());
        assertEquals(4, changes.get());
    }

    private void playBothHalves() {
        kickOff();
        ok(new ToFinished());
        game.advance();
        kickOff();
        ok(new ToFinished());
    }

    @Test
    void penaltyShootoutAlternatesKicksAndRecordsSingleShots() {
        refused(new StartPenaltyShootout());
        playBothHalves();
        ok(new StartPenaltyShootout());
        refused(new StartPenaltyShootout());
        GameControlData d = wire();
        assertEquals(SecondaryState.PENALTYSHOOT.code(), d.secondaryState());
        assertEquals(PlayState.INITIAL.code(), d.state());
        assertEquals(13, d.kickOffTeam(), "the team that kicked off the game shoots first");
        refused(new ToReady());
        ok(new ToSet());
        assertEquals(1, wire().team(13).penaltyShot());
        ok(new ToPlaying());
        assertEquals(60, wire().secondaryTime());
        secs(20);
        assertEquals(40, wire().secondaryTime());
        refused(new Goal(7));
        refused(new DropBall());
        refused(new StartSetPlay(13, SecondaryState.CORNER_KICK));
        ok(new Goal(13));
        d = wire();
        assertEquals(PlayState.FINISHED.code(), d.state());
        assertEquals(1, d.team(13).score());
        assertEquals(1, d.team(13).singleShots());
        assertFalse(game.advance(), "no half-time switch in a shoot-out");
        ok(new ToSet());
        assertEquals(7, wire().kickOffTeam());
        assertEquals(1, wire().team(7).penaltyShot());
        ok(new ToPlaying());
        ok(new ToFinished()); // missed
        assertEquals(0, wire().team(7).singleShots());
        ok(new ToSet());
        ok(new ToPlaying());
        ok(new Goal(13));
        assertEquals(0b11, wire().team(13).singleShots());
        assertEquals(2, wire().team(13).penaltyShot());
    }

    @Test
    void noShootoutAfterAWin() {
        kickOff();
        ok(new Goal(7));
        ok(new ToFinished());
        game.advance();
        kickOff();
        ok(new ToFinished());
        refused(new StartPenaltyShootout());
    }
}
