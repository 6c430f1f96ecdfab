package touchline.ui.window;

import javafx.geometry.Rectangle2D;
import javafx.stage.Screen;
import javafx.stage.Stage;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Properties;

/**
 * The size and place of the console window and its dialogs, remembered in one small file of
 * the user's settings. A window opens where it was closed; the first time (or when that place
 * is on no screen now) filling the screen up to a maximum size, centred. Sizes are set on the stage before it is shown,
 * so a window manager never gets to pick 200×200 (JavaFX 21's JDK-8316423).
 * A file that cannot be read or written only costs the remembering: logged once, never shown
 * as an error.
 */
public final class WindowPlaces {

    /** A first start fills a laptop's screen (up to the caller's maximum, centred on a larger one). */
    static final double FIRST_START_FRACTION = 1.0;

    private final SettingsFile settings;

    public WindowPlaces(Path file) {
        this.settings = new SettingsFile(file, "the window sizes");
    }

    public Path file() {
        return settings.file();
    }

    public synchronized Optional<WindowPlace> get(String window) {
        Properties p = read();
        try {
            return Optional.of(new WindowPlace(Double.parseDouble(p.getProperty(window + ".x")),
                    Double.parseDouble(p.getProperty(window + ".y")), Double.parseDouble(p.getProperty(window + ".width")),
                    Double.parseDouble(p.getProperty(window + ".height")),
                    Boolean.parseBoolean(p.getProperty(window + ".maximized"))));
        } catch (NullPointerException | NumberFormatException e) {
            return Optional.empty(); // never saved, or edited by hand into something else
        }
    }

    public synchronized void put(String window, WindowPlace place) {
        Properties p = read();
        p.setProperty(window + ".x", Double.toString(place.x()));
        p.setProperty(window + ".y", Double.toString(place.y()));
        p.setProperty(window + ".width", Double.toString(place.width()));
        p.setProperty(window + ".height", Double.toString(place.height()));
        p.setProperty(window + ".maximized", Boolean.toString(place.maximized()));
        settings.write(p, "Touchline window sizes and places");
    }

    /**
     * Sizes and places {@code stage} (not yet shown) as it was last closed, or at a share of the
     * screen at most {@code maxWidth} by {@code maxHeight}, and remembers it when it hides.
     */
    /** How long after showing a shrink by the window manager is undone. */
    static final double SHRINK_GUARD_SECONDS = 5;

    public void keep(Stage stage, String window, double maxWidth, double maxHeight) {
        Rectangle2D screen = Screen.getPrimary().getVisualBounds();
        List<Rectangle2D> screens = Screen.getScreens().stream().map(Screen::getVisualBounds).toList();
        WindowPlace place = get(window).filter(w -> w.reachableOn(screens)).map(w -> w.within(screen))
                .orElseGet(() -> WindowPlace.centred(screen, FIRST_START_FRACTION, maxWidth, maxHeight));
        stage.setX(place.x());
        stage.setY(place.y());
        stage.setWidth(place.width());
        stage.setHeight(place.height());
        stage.setMaximized(place.maximized());
        // JavaFX 21 on Linux (JDK-8316423, fixed in 22) lets the window manager shrink a window
        // shown with a size to about 200x200, sometimes well after it is mapped (seen on a
        // loaded machine): for the first seconds a shrink to under half the size is undone.
        stage.addEventHandler(javafx.stage.WindowEvent.WINDOW_SHOWN, e -> {
            Runnable restore = () -> {
                if (!stage.isMaximized() && (stage.getWidth() < place.width() / 2
                        || stage.getHeight() < place.height() / 2)) {
                    stage.setWidth(place.width());
                    stage.setHeight(place.height());
                    stage.setX(place.x());
                    stage.setY(place.y());
                }
            };
            javafx.beans.InvalidationListener undoShrink = o -> javafx.application.Platform.runLater(restore);
            stage.widthProperty().addListener(undoShrink);
            stage.heightProperty().addListener(undoShrink);
            javafx.application.Platform.runLater(restore);
            javafx.animation.PauseTransition settled = new javafx.animation.PauseTransition(
                    javafx.util.Duration.seconds(SHRINK_GUARD_SECONDS));
            settled.setOnFinished(done -> {
                stage.widthProperty().removeListener(undoShrink);
                stage.heightProperty().removeListener(undoShrink);
            });
            settled.play();
        });
        stage.addEventHandler(javafx.stage.WindowEvent.WINDOW_HIDING, e -> put(window, placeOf(stage, place)));
    }

    /** A maximised stage reports the screen's size: keep the size it had before. */
    private static WindowPlace placeOf(Stage stage, WindowPlace before) {
        if (stage.isMaximized()) {
            return new WindowPlace(before.x(), before.y(), before.width(), before.height(), true);
        }
        return new WindowPlace(stage.getX(), stage.getY(), stage.getWidth(), stage.getHeight(), false);
    }

    private Properties read() {
        return settings.read();
    }
}
