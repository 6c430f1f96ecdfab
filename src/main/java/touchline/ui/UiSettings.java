package touchline.ui;

import java.nio.file.Path;

/**
 * How the window starts: where named layouts live, dark or light theme, and whether to open
 * the demo arrangement (and switch the demo options on) for the simulated team.
 */
public record UiSettings(Path layoutDir, boolean dark, boolean demo) { }
