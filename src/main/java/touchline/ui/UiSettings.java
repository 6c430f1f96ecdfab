package touchline.ui;

import java.nio.file.Path;

/**
 * How the window starts: where named layouts live, dark or light theme, and whether to open
 * the demo arrangement (and switch the demo options on) for the simulated team. The sizes and
 * places of the windows are remembered beside the layouts.
 */
public record UiSettings(Path layoutDir, boolean dark, boolean demo) {

    public WindowPlaces windowPlaces() {
        return new WindowPlaces(layoutDir.resolve("windows.properties"));
    }
}
