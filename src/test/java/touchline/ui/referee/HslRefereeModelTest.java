package touchline.ui.referee;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.app.game.GameRuntime;
import touchline.game.ManualClock;
import touchline.game.hsl.Competition;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslPlayState;
import touchline.game.hsl.HslRules;
import touchline.game.hsl.HslState;
import touchline.game.hsl.SetPlay;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.testing.Await;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The HSL referee box without a window: which buttons are legal when, the call-then-robot penalty, texts. */
class HslRefereeModelTest {

    private final ManualClock clock = new ManualClock(0);
    private final List<GameRuntime> owners = new ArrayList<>();
    private HslRefereeModel model;

    /** The model over a started owner of {@code game}, as the referee tab builds it. */
    private HslRefereeModel modelOf(HslGame game) {
        GameRuntime owner = new GameRuntime(game);
        owner.start();
        owners.add(owner);
        return new HslRefereeModel(owner);
    }

    @AfterEach
    void stopOwners() {
        owners.forEach(GameRuntime::close);
    }

    @BeforeEach
    void game() {
        model = modelOf(new HslGame(HslRules.v7(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, clock));
    }

    /**
     * Frames until the owner answered every action enqueued, as the view's pulse takes them: an
     * action only enqueues, its outcome comes at the frame after the owner's answer.
     */
    private static void settle(HslRefereeModel m) throws InterruptedException {
        Await.until("the GameController's answer", () -> {
            m.refresh();
            return !m.waiting();
        });
    }

    private void ok(touchline.game.LeagueAction<? super HslState> a) throws InterruptedException {
        model.perform(a);
        settle(model);
        assertFalse(model.refused(), model.message());
    }

    /** Presses robot {@code player} on {@code side} and takes the outcome: whether it was applied. */
    private boolean press(int side, int player) throws InterruptedException {
        model.pressRobot(side, player);
        settle(model);
        return !model.refused();
    }

    private void kickOffAndPlay() throws InterruptedException {
        ok(model.ready());
        ok(model.set());
        ok(model.play());
    }

    @Test
    void initialAllowsOnlyTheKickOffOfTheTeamWhoseItIs() {
        assertTrue(model.legal(model.ready()));
        assertTrue(model.legal(model.setPlay(0, SetPlay.KICK_OFF)));
        assertFalse(model.legal(model.setPlay(1, SetPlay.KICK_OFF)), "team 14 kicks off in the second half");
        assertFalse(model.legal(model.stopOrResume()), "nothing to stop before play");
        assertFalse(model.legal(model.play()));
        assertFalse(model.legal(model.goal(0)));
        assertFalse(model.legal(model.setPlay(0, SetPlay.CORNER_KICK)));
        assertTrue(model.legal(model.timeout(1)));
        assertEquals(" 10:00", model.mainClock());
        assertEquals("Messages left 12000", model.budget(0));
        assertEquals("red, goalkeeper purple", model.colours(0));
        assertEquals(5, model.playersPerTeam());
    }

    @Test
    void kickOffReadySetPlayingThenStopAndResume() throws Exception {
        ok(model.ready());
        assertEquals(HslPlayState.READY, model.state().state());
        assertEquals("  0:45", model.secondaryClock());
        assertFalse(model.legal(model.play()), "the whistle comes after SET");
        ok(model.set());
        ok(model.play());
        assertEquals(HslPlayState.PLAYING, model.state().state());
        assertTrue(model.stateText().contains("robots still see SET"), model.stateText());
        assertEquals("Stop (Space)", model.stopOrResumeLabel());
        ok(model.stopOrResume());
        assertTrue(model.state().stopped());
        assertEquals("Resume (Space)", model.stopOrResumeLabel());
        assertTrue(model.stateText().contains("STOPPED"));
        ok(model.stopOrResume());
        assertFalse(model.state().stopped());
    }

    @Test
    void setPlaysWithoutReadyStopPlayAndBallFreeEndsThem() throws Exception {
        kickOffAndPlay();
        assertTrue(model.legal(model.setPlay(1, SetPlay.CORNER_KICK)));
        ok(model.setPlay(1, SetPlay.CORNER_KICK));
        assertTrue(model.state().stopped(), "a corner stops play at once");
        assertTrue(model.stateText().contains("corner kick 14"), model.stateText());
        ok(model.stopOrResume());
        assertTrue(model.legal(model.ballFree()));
        ok(model.ballFree());
        assertNull(model.state().setPlay());
    }

    @Test
    void anIllegalActionIsRefusedWithTheReason() throws Exception {
        model.perform(model.goal(0));
        settle(model);
        assertTrue(model.refused());
        assertTrue(model.message().startsWith("illegal now: goal 5"), model.message());
    }

    /**
     * The owner held inside its listener (the sender's wake-up, on the owner thread) after READY:
     * a goal pressed meanwhile only enqueues; unanswered past {@link GameRuntime#ANSWER_MS} on the
     * game's clock the line says so, and once the owner goes on the goal's refusal is shown.
     */
    @Test
    void anActionOnlyEnqueuesAndItsOutcomeComesAtAFrameAfterTheOwnerAnswered() throws Exception {
        try (touchline.testing.HeldOwner held = new touchline.testing.HeldOwner(owners.get(0))) {
            model.perform(model.ready());
            assertTrue(held.awaitHeld(), "the game's owner is held");
            model.perform(model.goal(0)); // no goal in READY
            model.refresh();
            assertTrue(model.waiting());
            assertEquals("", model.message(), "nothing answered yet");
            clock.advance(GameRuntime.ANSWER_MS);
            model.refresh();
            assertTrue(model.refused());
            assertEquals("the GameController did not answer within " + GameRuntime.ANSWER_MS + " ms", model.message());
        }
        settle(model);
        assertEquals(HslPlayState.READY, model.state().state());
        assertTrue(model.refused());
        assertTrue(model.message().startsWith("illegal now: goal 5"), model.message());
    }

    @Test
    void aGoalCountsAndGivesTheOtherTeamTheKickOff() throws Exception {
        kickOffAndPlay();
        ok(model.goal(0));
        assertEquals("1", model.score(0));
        assertEquals(HslPlayState.READY, model.state().state());
        assertEquals(14, model.state().kickingTeam());
    }

    @Test
    void thePenaltyIsChosenFirstThenTheRobotThenItsTimerStartsAndItComesBack() throws Exception {
        kickOffAndPlay();
        assertFalse(model.legal(model.robotAction(1, 3)), "no call chosen: a playing robot has nothing to undo");
        assertEquals("Playing", model.robotButtonText(1, 3));
        model.choose(HslPenalty.PUSHING);
        assertEquals(HslPenalty.PUSHING, model.chosen());
        assertEquals("Penalise", model.robotButtonText(1, 3));
        assertTrue(press(1, 3), model.message());
        assertNull(model.chosen(), "a call is used once");
        assertEquals(HslPenalty.PUSHING, model.state().teamOnSide(1).player(3).penalty());
        assertEquals("Start timer", model.robotButtonText(1, 3));
        assertTrue(model.robotText(1, 3, "online").contains("pushing wait"), model.robotText(1, 3, "online"));
        assertTrue(press(1, 3), "the robot is outside: its timer starts");
        assertEquals("Running", model.robotButtonText(1, 3));
        assertFalse(model.legal(model.robotAction(1, 3)), "not back before the time is served");
        clock.advance(45_000);
        model.refresh();
        assertEquals("Back in", model.robotButtonText(1, 3));
        assertTrue(press(1, 3));
        assertFalse(model.state().teamOnSide(1).player(3).isPenalised());
    }

    @Test
    void motionInStopOnlyWhileStoppedAndMotionInSetOnlyInSet() throws Exception {
        kickOffAndPlay();
        assertFalse(model.penaltyLegal(HslPenalty.MOTION_IN_STOP));
        assertFalse(model.penaltyLegal(HslPenalty.MOTION_IN_SET));
        model.choose(HslPenalty.MOTION_IN_STOP);
        assertNull(model.chosen(), "refused: no robot can get it now");
        assertTrue(model.refused());
        ok(model.stopOrResume());
        assertTrue(model.penaltyLegal(HslPenalty.MOTION_IN_STOP));
    }

    @Test
    void aSecondCautionSendsOff() throws Exception {
        kickOffAndPlay();
        model.choose(HslPenalty.CAUTIONED);
        assertTrue(press(0, 2));
        assertEquals(1, model.state().teamOnSide(0).player(2).cautions());
        model.choose(HslPenalty.CAUTIONED);
        assertTrue(press(0, 2));
        assertEquals(HslPenalty.SENT_OFF, model.state().teamOnSide(0).player(2).penalty());
        assertEquals("Out", model.robotButtonText(0, 2));
        assertFalse(model.legal(model.robotAction(0, 2)));
    }

    @Test
    void choosingTheSameCallAgainCancelsIt() throws Exception {
        kickOffAndPlay();
        model.choose(HslPenalty.PUSHING);
        model.choose(HslPenalty.PUSHING);
        assertNull(model.chosen());
    }

    @Test
    void additionalMinuteAfterAMinuteOutsidePlayAddsBudget() throws Exception {
        kickOffAndPlay();
        assertFalse(model.legal(model.additionalMinute()), "not during PLAYING");
        clock.advance(70_000);
        ok(model.droppedBall());
        assertTrue(model.legal(model.additionalMinute()));
        ok(model.additionalMinute());
        assertEquals("Messages left 12600", model.budget(0));
    }

    @Test
    void theSixOhReleaseHasNoCautions() {
        HslRefereeModel v6 = modelOf(new HslGame(HslRules.v6(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, clock));
        assertFalse(v6.calls().contains(HslPenalty.CAUTIONED));
        assertFalse(v6.calls().contains(HslPenalty.MOTION_IN_STOP));
        assertTrue(model.calls().contains(HslPenalty.CAUTIONED));
    }

    @Test
    void clocksKeepTheirWidth() {
        assertEquals(" 10:00", HslRefereeModel.clock(600));
        assertEquals("  0:05", HslRefereeModel.clock(5));
        assertEquals(" -0:05", HslRefereeModel.clock(-5));
        assertEquals(HslRefereeModel.clock(600).length(), model.secondaryClock().length());
    }
}
