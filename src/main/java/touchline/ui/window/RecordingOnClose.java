package touchline.ui.window;

import javafx.application.Platform;
import javafx.stage.Window;
import javafx.stage.WindowEvent;
import touchline.app.Recordings;

import java.util.function.Consumer;

/**
 * Closing the window ends a recording as its Stop button does, and never on the JavaFX thread:
 * a close asked for while recording keeps the window, says "finishing recording…" and closes it
 * once the file is finished (summary, footer) or the bound has passed (a stuck disk must not hold
 * the window for ever); a window hidden otherwise (by a program) hands the finish to a thread
 * and hides at once, and the process's way out waits for that finish.
 */
final class RecordingOnClose {

    private final Recordings recordings;
    private final Consumer<String> say;
    private final long boundMillis;
    private boolean finishing; // FX thread only

    /** @param say the status line; @param boundMillis how long the finish may take before the window closes anyway */
    RecordingOnClose(Recordings recordings, Consumer<String> say, long boundMillis) {
        this.recordings = recordings;
        this.say = say;
        this.boundMillis = boundMillis;
    }

    /** The window's close request: held while a recording is finished, then the window hides. */
    void request(WindowEvent close, Window window) {
        if (!finishing && recordings.current().isEmpty()) {
            return; // nothing recording: the window closes now
        }
        close.consume();
        if (finishing) {
            return;
        }
        finishing = true;
        say.accept("finishing recording…");
        recordings.finishThen(boundMillis, finished -> Platform.runLater(window::hide));
    }

    /** The window hides: a recording still running is finished on a thread of its own. */
    void hiding() {
        if (!finishing && recordings.current().isPresent()) {
            finishing = true;
            recordings.finishThen(boundMillis, finished -> { });
        }
    }
}
