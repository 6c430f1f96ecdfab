package touchline.cli;

import javafx.stage.Stage;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.ui.window.ConsoleWindow;
import touchline.ui.window.UiSettings;
import touchline.ui.window.LayoutStore;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.CountDownLatch;

/**
 * Opens the JavaFX console window; returns when the window is closed. The UDP port is bound
 * and the display checked before any window, so a port in use or a missing display ends the
 * command with one sentence and an exit code (see {@link StartFailure}).
 */
@Command(name = "console", mixinStandardHelpOptions = true,
        description = "Open the console window (robots, debug options, consoles, visualisations, layouts).")
final class ConsoleCommand implements java.util.concurrent.Callable<Integer> {

    @Mixin
    UdpOptions udp;

    @Mixin
    TeamBudgetOptions budget;

    @Mixin
    RemoteOptions remote;

    @Option(names = "--demo", description = "open the demo layout and switch the demo options on for every robot")
    boolean demo;

    @Option(names = "--light", description = "light theme (default: dark)")
    boolean light;

    @Option(names = "--layouts", description = "directory of named layouts (default: ~/.config/touchline/layouts)")
    String layouts;

    @Option(names = "--max-fps", defaultValue = "30", paramLabel = "N",
            description = "while data streams, redraw the views at most N times a second (1-60, default ${DEFAULT-VALUE});"
                    + " fewer saves a laptop's battery, and what is shown is up to 1/N s older")
    int maxFps;

    /** How long the way out waits for a recording's file to be finished. */
    static final long FINISH_RECORDING_MILLIS = 20_000;

    @Override
    public Integer call() throws Exception {
        touchline.ui.frame.FrameCap cap;
        try {
            cap = new touchline.ui.frame.FrameCap(maxFps);
        } catch (IllegalArgumentException e) {
            throw StartFailure.badInput(e.getMessage() + " (30 is the standard; 10 is plenty to watch a game on battery).");
        }
        remote.check();
        try (Console console = remote.remote() ? remote.startViewing() : udp.startConsole()) {
            remote.connectBridges(console.bridges());
            budget.guard(console.teamBudget(), udp.bind);
            StartMarks marks = new StartMarks(System.err, console.field().clock());
            console.field().robots().addPresenceListener(marks);
            String noDisplay = missingDisplay(System.getenv(), System.getProperty("glass.platform", ""),
                    System.getProperty("os.name", ""));
            if (noDisplay != null) {
                throw StartFailure.noDisplay(noDisplay);
            }
            try {
                FxThread.startToolkit();
            } catch (RuntimeException e) { // "Unable to open DISPLAY" and the like
                throw StartFailure.noDisplay("JavaFX could not open it (" + e.getMessage() + ")");
            }
            // Ctrl+C or SIGTERM while the window is open: the recording is finished before the JVM exits
            Thread hook = new Thread(() -> console.recordings().finish(FINISH_RECORDING_MILLIS), "touchline-console-stop");
            Runtime.getRuntime().addShutdownHook(hook);
            CountDownLatch closed = new CountDownLatch(1);
            UiSettings settings = new UiSettings(layouts != null ? Path.of(layouts) : LayoutStore.defaultDir(), !light, demo, cap);
            FxThread.run(() -> {
                Stage stage = new Stage();
                stage.addEventHandler(javafx.stage.WindowEvent.WINDOW_HIDDEN, e -> closed.countDown());
                stage.addEventHandler(javafx.stage.WindowEvent.WINDOW_SHOWN, e -> marks.windowShown());
                ConsoleWindow window = new ConsoleWindow(console, settings).show(stage, true);
                if (StartMarks.trainingFrames() > 0) {
                    window.closeAfterFrames(StartMarks.trainingFrames());
                }
            });
            closed.await();
            javafx.application.Platform.exit();
            console.recordings().finish(FINISH_RECORDING_MILLIS);
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // the hook is running already; it finishes the same recording
            }
            return 0;
        }
    }

    /** Why there is no display to open a window on, or null when there is one (or no way to tell). */
    static String missingDisplay(Map<String, String> env, String glassPlatform, String osName) {
        if (!osName.toLowerCase(java.util.Locale.ROOT).contains("linux") || glassPlatform.equalsIgnoreCase("Monocle")) {
            return null;
        }
        boolean x11 = env.getOrDefault("DISPLAY", "").isBlank();
        boolean wayland = env.getOrDefault("WAYLAND_DISPLAY", "").isBlank();
        return x11 && wayland ? "neither DISPLAY nor WAYLAND_DISPLAY is set" : null;
    }
}
