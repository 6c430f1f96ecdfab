package touchline.ui.window;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.UiTest;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Issue 14's start: the window shows before its views, which follow after the first frame. */
@UiTest
class FastStartUiTest {

    @TempDir
    Path layouts;

    @Test
    void theWindowShowsFirstAndTheLayoutsViewsFollowAfterTheFirstFrame() throws Exception {
        // as the tests show it: the layout's views are there when show returns
        ConsoleWindowFixture atOnce = new ConsoleWindowFixture(layouts);
        int views = atOnce.viewsWhenShown;
        atOnce.close();
        assertTrue(views > 0, "no views when show returned");
        // as `touchline console` shows it: none yet when the window shows, all of them after the first frame
        ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts, ConsoleWindowFixture.loopback(), true);
        try {
            assertEquals(0, ui.viewsWhenShown, "views built before the window was shown");
            assertTrue(ui.fx(() -> ui.window.scene().getWindow().isShowing()));
            ui.await(30, () -> ui.window.shell().openViews().size() == views);
        } finally {
            ui.close();
        }
    }

    @Test
    void aTrainingRunsWindowClosesItselfAfterItsFrames() throws Exception {
        ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts, ConsoleWindowFixture.loopback(), true);
        try {
            assertTrue(ui.fx(() -> ui.window.scene().getWindow().isShowing()));
            ui.fxRun(() -> ui.window.closeAfterFrames(3));
            ui.await(30, () -> !ui.window.scene().getWindow().isShowing());
        } finally {
            ui.close();
        }
    }
}
