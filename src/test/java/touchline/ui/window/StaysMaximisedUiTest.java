package touchline.ui.window;

import javafx.geometry.Rectangle2D;
import javafx.stage.Screen;
import javafx.stage.Stage;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * The system's file chooser is modal by nature, and under openbox it took a maximised window out
 * of its maximised state for good (issue 36 item 7; seen by hand, a window manager is needed to
 * see it). A window that was maximised, or fills its screen because the window manager maximised it
 * (JavaFX reads false then), is maximised again when the chooser closes; a smaller one is left alone.
 */
@Tag("ui")
class StaysMaximisedUiTest {

    @TempDir
    Path layouts;

    @Test
    void aWindowThatFilledItsScreenIsMaximisedAgainAfterTheChooserAndASmallerOneIsLeftAlone() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            Stage stage = ui.fx(() -> (Stage) ui.window.scene().getWindow());
            Rectangle2D screen = ui.fx(() -> Screen.getPrimary().getVisualBounds());
            ui.fxRun(() -> {
                stage.setMaximized(false);
                stage.setX(screen.getMinX());
                stage.setY(screen.getMinY());
                stage.setWidth(screen.getWidth());
                stage.setHeight(screen.getHeight() - 30); // the window manager's title bar
            });
            assertFalse(ui.fx(stage::isMaximized));
            String chosen = ui.fx(() -> new StaysMaximised(stage).during(() -> "recording.mcap"));
            assertEquals("recording.mcap", chosen, "the chooser's answer is handed on");
            ui.await(30, stage::isMaximized);

            ui.fxRun(() -> {
                stage.setMaximized(false);
                stage.setWidth(screen.getWidth() / 2);
                stage.setHeight(screen.getHeight() / 2);
            });
            ui.fx(() -> new StaysMaximised(stage).during(() -> null));
            ui.fxRun(() -> { }); // after what the chooser's end queued on the FX thread (it queues in order)
            assertFalse(ui.fx(stage::isMaximized), "a window half its screen's size stays as it is");
        }
    }
}
