package touchline.ui;

import javafx.application.Application;
import touchline.ui.render.RenderDefaults;

/**
 * Plain entry point: JavaFX refuses to start an Application subclass as the main class from
 * the class path, so this class (which is not one) launches {@link TouchlineApp}.
 */
public final class Launcher {

    private Launcher() { }

    public static void main(String[] args) {
        new RenderDefaults().apply();
        Application.launch(TouchlineApp.class, args);
    }
}
