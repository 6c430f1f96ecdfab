package touchline.ui.referee;

import javafx.scene.Parent;
import javafx.scene.Scene;
import javafx.scene.control.ButtonBase;
import javafx.scene.control.Label;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.app.game.GameRuntime;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.game.PlayState;
import touchline.game.RefereedGame;
import touchline.game.ToReady;
import touchline.game.hsl.Competition;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslPlayState;
import touchline.game.hsl.HslRules;
import touchline.game.hsl.SetPlay;
import touchline.game.hsl.HslStartSetPlay;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.testing.Await;
import touchline.testing.HeldOwner;
import touchline.ui.frame.View;


import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

/**
 * A referee's click only enqueues: with the game's owner held (inside its listener, on the owner
 * thread, after an action the test enqueued), a click on the JavaFX thread returns at once, the
 * owner is let go by that same JavaFX step, and the click's refusal then shows in the box with the
 * words of the rules. A click that waited for its outcome would hold the JavaFX thread until it
 * gave up (the owner let go only afterwards) and never show the refusal.
 */
class RefereeClickTest {

    private final ManualClock clock = new ManualClock(0);
    private HeldOwner held;
    private GameRuntime owner;

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    @AfterEach
    void letGo() {
        held.close();
        owner.close();
    }

    /** A started owner of {@code game} that holds its thread at the first change until {@link #held} is closed. */
    private GameRuntime heldAtTheFirstChange(RefereedGame game) {
        owner = new GameRuntime(game);
        held = new HeldOwner(owner);
        owner.start();
        return owner;
    }

    private static <V extends View> V shown(java.util.concurrent.Callable<V> make) throws Exception {
        return fx(() -> {
            V v = make.call();
            new Scene((Parent) v.node());
            return v;
        });
    }

    /** Presses {@code id} and, in the same JavaFX step, lets the owner go on. */
    private void pressThenLetGo(View view, String id) throws Exception {
        fx(() -> {
            ((ButtonBase) view.node().lookup("#" + id)).fire();
            held.close();
            return null;
        });
    }

    /** Frames of {@code view} until its message line says what {@code prefix} begins; that line. */
    private static String awaitMessage(View view, String prefix) throws Exception {
        String[] line = {""};
        Await.until("the message line to begin with '" + prefix + "'", () -> {
            try {
                line[0] = fx(() -> {
                    view.refresh(null);
                    return ((Label) view.node().lookup("#gc-message")).getText();
                });
            } catch (Exception e) {
                throw new AssertionError(e);
            }
            return line[0].startsWith(prefix);
        });
        return line[0];
    }

    @Test
    void anHlClickWhileTheOwnerIsBusyReturnsAtOnceAndItsRefusalShows() throws Exception {
        GameRuntime game = heldAtTheFirstChange(new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock));
        GameControllerView view = shown(() -> new GameControllerView(game, null));
        game.perform(new ToReady());
        assertTrue(held.awaitHeld(), "the game's owner is held");
        pressThenLetGo(view, "gc-play"); // no whistle in READY
        String line = awaitMessage(view, "illegal now: ");
        assertTrue(line.contains("READY"), line);
        assertEquals(PlayState.READY, game.snapshot().hl().state());
        assertEquals("-fx-text-fill: #c00;", fx(() -> view.node().lookup("#gc-message").getStyle()));
    }

    @Test
    void anHslClickWhileTheOwnerIsBusyReturnsAtOnceAndItsRefusalShows() throws Exception {
        GameRuntime game = heldAtTheFirstChange(new HslGame(HslRules.v7(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, clock));
        HslRefereeView view = shown(() -> new HslRefereeView(new HslRefereeModel(game), null, null));
        game.perform(new HslStartSetPlay(5, SetPlay.KICK_OFF)); // READY, as if a key had been pressed
        assertTrue(held.awaitHeld(), "the game's owner is held");
        // the box last drew INITIAL, where Ready is allowed: a second Ready, refused by the rules
        pressThenLetGo(view, "gc-ready");
        awaitMessage(view, "illegal now: ");
        assertEquals(HslPlayState.READY, game.snapshot().hslAt(game.now()).state());
        assertTrue(fx(() -> view.model().refused()));
    }
}
