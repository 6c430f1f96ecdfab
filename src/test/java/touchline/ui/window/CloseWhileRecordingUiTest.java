package touchline.ui.window;

import javafx.scene.control.Label;
import javafx.stage.Stage;
import javafx.stage.WindowEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.record.HeldDisk;
import touchline.testing.UiTest;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Issue 38: closing the window while recording does not block the JavaFX thread. With the
 * recording's disk held (its file cannot be finished yet), a close request returns, the FX
 * thread goes on, the window stays and says "finishing recording…"; released, the file is
 * finished and the window closes.
 */
@UiTest
class CloseWhileRecordingUiTest {

    /** The last bytes of a finished MCAP file (after its footer). */
    private static final byte[] MCAP_MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

    @TempDir
    Path dir;
    private ConsoleWindowFixture ui;

    @Test
    void theFxThreadGoesOnWhileTheRecordingIsFinishedAndTheWindowClosesWhenItIs() throws Exception {
        Path file = dir.resolve("held.mcap");
        Stage stage = (Stage) ui.window.scene().getWindow();
        try (HeldDisk disk = new HeldDisk(ui.console.recordings().start(file))) {
            ui.fxRun(() -> stage.fireEvent(new WindowEvent(stage, WindowEvent.WINDOW_CLOSE_REQUEST)));
            // the FX thread is free again while the finish is held: a step on it sees the window as it is now
            boolean showing = ui.fx(stage::isShowing);
            String said = ui.fx(() -> ((Label) ui.window.status().lookup("#status-message")).getText());
            assertTrue(showing, "the window stays while its recording is being finished");
            assertEquals("finishing recording…", said);
            assertTrue(ui.console.recordings().current().isPresent(), "the finish is still held");

            disk.release();
            ui.await(30, () -> !stage.isShowing());
        }
        assertTrue(ui.console.recordings().current().isEmpty(), "the recording ended with the window");
        byte[] bytes = Files.readAllBytes(file);
        assertArrayEquals(MCAP_MAGIC, Arrays.copyOfRange(bytes, bytes.length - MCAP_MAGIC.length, bytes.length),
                "the file is finished (footer and closing magic)");
    }
}
