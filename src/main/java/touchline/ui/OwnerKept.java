package touchline.ui;

import javafx.stage.Stage;
import javafx.stage.Window;

import java.util.function.Function;

/**
 * Shows a native dialog (a file chooser) over a window and gives the window back the state it
 * had: on Linux (GTK under a window manager, seen with openbox) the main window loses its
 * maximised state while the native dialog is up and does not get it back when it closes.
 */
public final class OwnerKept {

    private final Window owner;

    public OwnerKept(Window owner) {
        this.owner = owner;
    }

    /** Runs {@code dialog} (it blocks until the user answers) and maximises the owner again if it was. */
    public <T> T show(Function<Window, T> dialog) {
        boolean maximized = owner instanceof Stage s && s.isMaximized();
        try {
            return dialog.apply(owner);
        } finally {
            if (maximized && owner instanceof Stage s && !s.isMaximized()) {
                s.setMaximized(true);
            }
        }
    }
}
