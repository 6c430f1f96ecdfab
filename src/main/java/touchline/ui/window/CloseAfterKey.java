package touchline.ui.window;

import javafx.application.Platform;
import javafx.stage.Stage;

/**
 * Closes a window a key asked to close once that key's events are delivered, never inside them.
 * On GTK a window closed during a key's PRESSED event left the same key's TYPED event to use the
 * freed window (JDK-8301219, fixed in JavaFX 22: Ctrl+K, a name, Enter killed the console). The
 * close is queued behind the key, so a JavaFX without that fix is safe too; a key repeated before
 * the close is taken once.
 */
final class CloseAfterKey {

    private final Stage stage;
    private boolean closing;

    CloseAfterKey(Stage stage) {
        this.stage = stage;
    }

    /** Closes the window after the current event, then does {@code next}. */
    void close(Runnable next) {
        if (closing) {
            return;
        }
        closing = true;
        Platform.runLater(() -> {
            stage.close();
            next.run();
        });
    }

    void close() {
        close(() -> { });
    }
}
