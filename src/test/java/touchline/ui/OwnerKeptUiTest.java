package touchline.ui;

import javafx.stage.Stage;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A native file dialog (Export CSV…, the recording's Browse…) leaves the main window maximised:
 * GTK under a window manager un-maximises the owner while the dialog is up (seen under openbox at
 * 1280×720). Monocle has no native dialog: the dialog here does what GTK did to the window.
 */
@Tag("ui")
class OwnerKeptUiTest {

    @TempDir
    Path layouts;
    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui = new ConsoleWindowFixture(layouts);
    }

    @AfterEach
    void close() throws Exception {
        ui.close();
    }

    @Test
    void aMaximisedWindowIsMaximisedAgainWhenTheDialogCloses() throws Exception {
        Stage stage = ui.fx(() -> (Stage) ui.window.scene().getWindow());
        ui.fxRun(() -> stage.setMaximized(true));
        ui.await(30, stage::isMaximized);
        String answer = ui.fx(() -> new OwnerKept(stage).show(owner -> {
            ((Stage) owner).setMaximized(false); // what the native dialog did to its owner
            return "plot.csv";
        }));
        assertEquals("plot.csv", answer);
        assertTrue(ui.fx(stage::isMaximized), "maximised again");

        ui.fxRun(() -> stage.setMaximized(false));
        ui.fx(() -> new OwnerKept(stage).show(owner -> null));
        assertFalse(ui.fx(stage::isMaximized), "a window that was not maximised stays so");
    }
}
