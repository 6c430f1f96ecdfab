package touchline.ui.window;

import java.nio.file.Path;
import touchline.ui.frame.FrameCap;

/**
 * How the window starts: where named layouts live, dark or light theme, whether to open
 * the demo arrangement (and switch the demo options on) for the simulated team, and how often
 * the views may redraw while data streams ({@code --max-fps}). The sizes and places of the
 * windows are remembered beside the layouts.
 */
public record UiSettings(Path layoutDir, boolean dark, boolean demo, FrameCap frameCap) {

    /** With the standard frame cap (30 a second). */
    public UiSettings(Path layoutDir, boolean dark, boolean demo) {
        this(layoutDir, dark, demo, FrameCap.standard());
    }

    public WindowPlaces windowPlaces() {
        return new WindowPlaces(layoutDir.resolve("windows.properties"));
    }
}
