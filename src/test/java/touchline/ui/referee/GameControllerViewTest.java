package touchline.ui.referee;

import javafx.event.Event;
import javafx.scene.Scene;
import javafx.scene.control.Button;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.app.game.GameRuntime;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.game.Penalty;
import touchline.game.PlayState;

import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

/** The GameController tab on a headless stage: buttons and keys drive the game. */
class GameControllerViewTest {

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    private static void click(GameRuntime owner, GameControllerView view, String id) throws Exception {
        fx(() -> {
            ((Button) view.node().lookup("#" + id)).fire();
            return null;
        });
        answered(owner, view);
    }

    /**
     * A click only enqueues: the owner answers in arrival order, so once a timer event enqueued
     * after it is done (the clock stands still: nothing else changes), so is the click; then a frame.
     */
    private static void answered(GameRuntime owner, GameControllerView view) throws Exception {
        owner.tick().get(30, TimeUnit.SECONDS);
        fx(() -> {
            view.refresh(null);
            return null;
        });
    }

    @Test
    void buttonsAndKeysRefereeAGame() throws Exception {
        ManualClock clock = new ManualClock(0);
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock);
        GameRuntime owner = new GameRuntime(game);
        owner.start();
        GameControllerView view = fx(() -> {
            GameControllerView v = new GameControllerView(owner, null);
            new Scene((javafx.scene.Parent) v.node());
            return v;
        });
        assertTrue(fx(() -> clockText(view)).startsWith("INITIAL"));
        click(owner, view, "gc-ready");
        assertEquals(PlayState.READY, game.snapshot().state());
        fx(() -> {
            Event.fireEvent(view.node(), new KeyEvent(KeyEvent.KEY_PRESSED, "", "", KeyCode.S, false, false, false,
                    false));
            return null;
        });
        answered(owner, view);
        assertEquals(PlayState.SET, game.snapshot().state());
        click(owner, view, "gc-play");
        click(owner, view, "gc-goal-1");
        assertEquals(1, game.snapshot().team(7).score());
        assertTrue(fx(() -> clockText(view)).contains("13 0:1 7"), fx(() -> clockText(view)));
        click(owner, view, "gc-play"); // illegal in READY: refused, shown, nothing changes
        assertEquals(PlayState.READY, game.snapshot().state());
        click(owner, view, "gc-robot-0-2");
        assertEquals(Penalty.PHYSICAL_CONTACT, game.snapshot().team(13).player(2).penalty());
        clock.advance(12_000);
        fx(() -> {
            view.refresh(null);
            return null;
        });
        assertTrue(fx(() -> view.robotText(0, 2)).contains("physical_contact 18s"), fx(() -> view.robotText(0, 2)));
        click(owner, view, "gc-robot-0-2");
        assertEquals(Penalty.NONE, game.snapshot().team(13).player(2).penalty());
        click(owner, view, "gc-undo");
        assertEquals(Penalty.PHYSICAL_CONTACT, game.snapshot().team(13).player(2).penalty());
        assertTrue(fx(() -> view.robotText(1, 5)).contains("substitute"));
        owner.close();
    }

    /** The clock line as the tab shows it (FX thread). */
    private static String clockText(GameControllerView view) {
        return ((javafx.scene.control.Label) view.node().lookup("#gc-clock")).getText();
    }
}
