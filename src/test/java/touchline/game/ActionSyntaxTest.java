package touchline.game;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

class ActionSyntaxTest {

    private final ActionSyntax syntax = new ActionSyntax();
    private final ManualClock clock = new ManualClock(0);
    private final Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock);

    private LeagueAction<? super GameState> parse(String line) {
        ActionSyntax.Parsed p = syntax.parse(line, game.snapshot());
        assertNull(p.error(), line);
        return p.action();
    }

    private String error(String line) {
        ActionSyntax.Parsed p = syntax.parse(line, game.snapshot());
        assertNull(p.action(), line);
        assertNotNull(p.error());
        return p.error();
    }

    @Test
    void parsesEveryCommand() {
        assertEquals(new ToReady(), parse("ready"));
        assertEquals(new ToSet(), parse(" SET "));
        assertEquals(new ToPlaying(), parse("play"));
        assertEquals(new ToFinished(), parse("finish"));
        assertEquals(new Goal(13), parse("goal 13"));
        assertEquals(new SetKickOff(7), parse("kickoff 7"));
        assertEquals(new Penalize(7, 2, Penalty.PHYSICAL_CONTACT), parse("penalty 7 2 physical_contact"));
        assertEquals(new Unpenalize(7, 2), parse("unpenalise 7 2"));
        assertEquals(new Card(7, 3, Card.Kind.YELLOW), parse("card 7 3 yellow"));
        assertEquals(new Card(13, 1, Card.Kind.WARNING), parse("card 13 1 warn"));
        assertEquals(new Substitute(7, 1, 5), parse("substitute 7 1 5"));
        assertEquals(new SetGoalkeeper(7, 2), parse("goalkeeper 7 2"));
        assertEquals(new StartSetPlay(13, SecondaryState.DIRECT_FREEKICK), parse("freekick 13 direct"));
        assertEquals(new StartSetPlay(13, SecondaryState.INDIRECT_FREEKICK), parse("freekick 13 indirect"));
        assertEquals(new StartSetPlay(7, SecondaryState.CORNER_KICK), parse("corner 7"));
        assertEquals(new StartSetPlay(7, SecondaryState.GOAL_KICK), parse("goalkick 7"));
        assertEquals(new StartSetPlay(7, SecondaryState.THROW_IN), parse("throwin 7"));
        assertEquals(new StartSetPlay(7, SecondaryState.PENALTYKICK), parse("penaltykick 7"));
        assertEquals(new SetPlayStep(SetPlayStep.Step.PREPARE), parse("prepare"));
        assertEquals(new SetPlayStep(SetPlayStep.Step.EXECUTE), parse("execute"));
        assertEquals(new SetPlayStep(SetPlayStep.Step.ABORT), parse("abort"));
        assertEquals(new SetPlayStep(SetPlayStep.Step.READY), parse("setplay ready"));
        assertEquals(new DropBall(), parse("dropball"));
        assertEquals(new Timeout(13), parse("timeout 13"));
    }

    @Test
    void readyDuringASetPlayIsTheSetPlayStep() {
        game.perform(new ToReady());
        game.perform(new ToSet());
        game.perform(new ToPlaying());
        game.perform(new StartSetPlay(13, SecondaryState.CORNER_KICK));
        assertEquals(new SetPlayStep(SetPlayStep.Step.READY), parse("ready"));
    }

    @Test
    void badLinesBecomeMessages() {
        error("");
        error("jump");
        error("goal");
        error("goal x");
        error("goal 13 7");
        error("penalty 7 2 tickling");
        error("penalty 7 2 substitute");
        error("card 7 2 blue");
        error("freekick 13 sideways");
        error("set now");
    }
}
