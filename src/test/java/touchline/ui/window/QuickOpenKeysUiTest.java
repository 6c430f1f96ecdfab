package touchline.ui.window;

import javafx.event.Event;
import javafx.event.EventDispatchChain;
import javafx.event.EventDispatcher;
import javafx.scene.control.TextField;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;
import javafx.stage.Stage;
import javafx.stage.Window;
import javafx.stage.WindowEvent;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.UiTest;
import touchline.ui.window.LayoutNode;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Issue 36 item 1: Ctrl+K, Enter or Escape, 500 times in the real window (headless). A window
 * closed inside a key's events crashed GTK (JDK-8301219): the quick-open and help windows close
 * after the key's events, never while one of them is being delivered.
 */
@UiTest
@Tag("integration")
class QuickOpenKeysUiTest {

    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("robots", ""))))));
    }

    /** Counts, on the FX thread, the key events a window is delivering and the closes that happened inside one. */
    private static final class KeyWatch implements EventDispatcher {
        private final EventDispatcher original;
        private int delivering;
        final List<String> closedInsideAKey = new ArrayList<>();

        KeyWatch(Stage stage) {
            original = stage.getEventDispatcher();
            stage.addEventHandler(WindowEvent.WINDOW_HIDDEN, e -> {
                if (delivering > 0) {
                    closedInsideAKey.add(stage.getTitle());
                }
            });
        }

        @Override
        public Event dispatchEvent(Event event, EventDispatchChain tail) {
            boolean key = event instanceof KeyEvent;
            delivering += key ? 1 : 0;
            try {
                return original.dispatchEvent(event, tail);
            } finally {
                delivering -= key ? 1 : 0;
            }
        }
    }

    private Optional<Stage> shown(String titlePrefix) {
        return Window.getWindows().stream().filter(w -> w instanceof Stage s && s.isShowing() && s.getTitle() != null
                && s.getTitle().startsWith(titlePrefix)).map(w -> (Stage) w).findFirst();
    }

    /** Ctrl+K in the focused main window; the quick-open's filter has the keyboard; its key deliveries watched. */
    private KeyWatch quickOpenByKey() throws Exception {
        ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
        ui.await(30, () -> ui.window.scene().getWindow().isFocused() && shown("Open view").isEmpty());
        ui.robot.press(KeyCode.CONTROL).type(KeyCode.K).release(KeyCode.CONTROL);
        ui.await(30, () -> shown("Open view").map(s -> s.isFocused()
                && s.getScene().getFocusOwner() == s.getScene().lookup("#quick-open-filter")).orElse(false));
        return ui.fx(() -> {
            Stage stage = shown("Open view").orElseThrow();
            KeyWatch watch = new KeyWatch(stage);
            stage.setEventDispatcher(watch);
            return watch;
        });
    }

    @Test
    void quickOpenOpensAndClosesByEnterAndEscape500TimesAndNeverClosesInsideAKey() throws Exception {
        for (int i = 0; i < 500; i++) {
            KeyWatch watch = quickOpenByKey();
            boolean enter = i % 2 == 0;
            if (enter) {
                String view = i % 4 == 0 ? "network" : "robots";
                ui.fxRun(() -> ((TextField) shown("Open view").orElseThrow().getScene().lookup("#quick-open-filter"))
                        .setText(view));
                ui.robot.type(KeyCode.ENTER);
            } else {
                ui.robot.type(KeyCode.ESCAPE);
            }
            ui.await(30, () -> shown("Open view").isEmpty());
            assertEquals(List.of(), ui.fx(() -> watch.closedInsideAKey), "round " + i + (enter ? " (Enter)" : " (Escape)")
                    + ": the window closed while a key was being delivered");
        }
        List<String> open = ui.fx(() -> ui.window.shell().openViews().stream().map(v -> v.spec().id()).sorted().toList());
        assertEquals(List.of("network", "robots"), open, "Enter opened the chosen view or brought it to the front");
        assertTrue(ui.fx(() -> shown("Open view").isEmpty()));
    }

    @Test
    void escapeClosesTheHelpAfterTheKey() throws Exception {
        ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
        ui.await(30, () -> ui.window.scene().getWindow().isFocused());
        ui.robot.press(KeyCode.CONTROL).type(KeyCode.SLASH).release(KeyCode.CONTROL);
        ui.await(30, () -> shown("Help — ").map(Stage::isFocused).orElse(false));
        KeyWatch watch = ui.fx(() -> {
            Stage stage = shown("Help — ").orElseThrow();
            KeyWatch w = new KeyWatch(stage);
            stage.setEventDispatcher(w);
            return w;
        });
        ui.robot.type(KeyCode.ESCAPE);
        ui.await(30, () -> shown("Help — ").isEmpty());
        assertEquals(List.of(), ui.fx(() -> watch.closedInsideAKey));
    }
}
