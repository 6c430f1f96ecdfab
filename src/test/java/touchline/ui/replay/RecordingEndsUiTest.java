package touchline.ui.replay;

import javafx.scene.control.Label;
import javafx.scene.control.TextField;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.PythonMcap;
import touchline.testing.Requirement;
import touchline.testing.RobotProcess;
import touchline.testing.UiTest;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ConsoleWindowFixture;

/**
 * The window's ways of ending a recording leave a finished file, as Ctrl+C and SIGTERM do for
 * {@code record} (RecordingEndsTest): recording is started from the Record &amp; replay view
 * while a real simulated robot sends on loopback, then ended by the Stop button or by closing
 * the window, and the file is read by the independent Python {@code mcap} reader through its
 * summary and indexes (footer, statistics, every index entry checked).
 */
@UiTest
@Tag("integration")
@Tag("interop")
class RecordingEndsUiTest {

    @TempDir
    Path dir;
    private ConsoleWindowFixture ui;
    private RobotProcess robot;

    @BeforeEach
    void open() throws Exception {
        Requirement.robotSide("touchline-robot");
        PythonMcap.require("mcap");
        ui.fxRun(() -> ui.window.open("replay", ViewSource.NONE));
        robot = RobotProcess.robot(5, ui.port()).start();
    }

    @AfterEach
    void close() throws Exception {
        if (robot != null) {
            robot.close();
        }
    }

    private Path startRecordingFromTheWindow() throws Exception {
        Path file = dir.resolve("session.mcap");
        ui.await(10, () -> ui.robot.lookup("#record-path").tryQuery().isPresent());
        ui.fxRun(() -> ui.robot.lookup("#record-path").queryAs(TextField.class).setText(file.toString()));
        press("#record-toggle");
        ui.await(10, () -> counters().startsWith("Recording:"));
        // the robot's own traffic (status, replies to the console's requests) reaches the file
        try {
            ui.await(15, () -> ui.console.recordings().current().map(s -> s.written() >= 3).orElse(false));
        } catch (java.util.concurrent.TimeoutException e) {
            throw new AssertionError("the robot's traffic did not reach the recording: " + ui.console.recordings().current()
                    + ", robot alive " + robot.isAlive() + ", its output: " + robot.stdout(), e);
        }
        return file;
    }

    /** Presses the button once it can be pressed (on a loaded machine the view's skin may join a pulse later). */
    private void press(String id) throws Exception {
        ui.await(10, () -> ui.robot.lookup(id).tryQuery().map(n -> n.getScene() != null && !n.isDisabled())
                .orElse(false));
        ui.fxRun(() -> ui.robot.lookup(id).queryAs(javafx.scene.control.Button.class).fire());
    }

    private String counters() {
        return ui.robot.lookup("#record-counters").queryAs(Label.class).getText();
    }

    @Test
    void theStopButtonFinishesTheFile() throws Exception {
        Path file = startRecordingFromTheWindow();
        press("#record-toggle");
        ui.await(10, () -> counters().startsWith("Stopped:"));
        assertFinished(file);
    }

    @Test
    void closingTheWindowWhileRecordingFinishesTheFile() throws Exception {
        Path file = startRecordingFromTheWindow();
        // what the window's close button does: the stage hides, and the app's way out follows
        ui.fxRun(() -> ui.window.scene().getWindow().hide());
        // finished off the FX thread (issue 38): it ends soon after the window
        ui.await(30, () -> ui.console.recordings().current().isEmpty());
        assertFinished(file);
    }

    /** Read through the summary and indexes by the Python reader: footer, statistics, index entries all agree. */
    private static void assertFinished(Path file) throws Exception {
        String[] read = PythonMcap.run(PythonMcap.INDEXED_READ, file).split("\n");
        String[] f = read[read.length - 1].split(" ");
        long messages = Long.parseLong(f[0]);
        assertTrue(messages >= 3, "messages read through the index: " + String.join(" ", f));
        assertEquals(f[0], f[1], "the statistics count every message");
        assertEquals(f[2], f[3], "every chunk index matches its chunk");
        assertEquals(f[0], f[4], "every message-index entry points to its message");
        assertEquals("5", f[5], "the summary offsets point to their groups");
    }
}
