package touchline.ui.window;

import javafx.geometry.Rectangle2D;
import javafx.stage.Screen;
import javafx.stage.Stage;
import javafx.stage.Window;

import java.util.function.Supplier;

/**
 * Keeps a maximised window maximised across the system's file chooser (a GTK dialog, modal by
 * nature): while it is up, JavaFX on Linux fixes the size of the application's windows and a
 * window manager (openbox) takes a maximised one out of its maximised state for good. JavaFX
 * does not always know the window was maximised (maximised by the window manager's title bar it
 * reads false), so a window that fills its screen counts as maximised too and is maximised again
 * when the chooser closes. Dialogs of our own are not modal instead ({@link NameDialog},
 * {@link ConfirmDialog}).
 */
public final class StaysMaximised {

    /** Slack for a window manager's frame and panels: a window this close to its screen's size fills it. */
    static final double FILLS_SLACK = 64;

    private final Window owner;

    public StaysMaximised(Window owner) {
        this.owner = owner;
    }

    /** Shows the dialog ({@code show} returns when it closes) and maximises the owner again if it was. */
    public <T> T during(Supplier<T> show) {
        boolean maximised = owner instanceof Stage s && (s.isMaximized() || fillsItsScreen(s));
        try {
            return show.get();
        } finally {
            if (maximised && owner instanceof Stage s) {
                // after the dialog's events: the owner is resizable again only then
                javafx.application.Platform.runLater(() -> {
                    s.setMaximized(false);
                    s.setMaximized(true);
                });
            }
        }
    }

    static boolean fillsItsScreen(Stage s) {
        Rectangle2D screen = Screen.getScreensForRectangle(s.getX(), s.getY(), s.getWidth(), s.getHeight()).stream()
                .findFirst().orElse(Screen.getPrimary()).getVisualBounds();
        return s.getWidth() >= screen.getWidth() - FILLS_SLACK && s.getHeight() >= screen.getHeight() - FILLS_SLACK;
    }
}
