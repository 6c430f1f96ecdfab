package touchline.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import touchline.ui.TouchlineApp;

import java.util.ArrayList;
import java.util.List;

/** Opens the JavaFX console window; returns when the window is closed. */
@Command(name = "console", mixinStandardHelpOptions = true,
        description = "Open the console window (robots, debug options, consoles, visualisations, layouts).")
final class ConsoleCommand implements java.util.concurrent.Callable<Integer> {

    @Mixin
    UdpOptions udp;

    @Option(names = "--demo", description = "open the demo layout and switch the demo options on for every robot")
    boolean demo;

    @Option(names = "--light", description = "light theme (default: dark)")
    boolean light;

    @Option(names = "--layouts", description = "directory of named layouts (default: ~/.config/touchline/layouts)")
    String layouts;

    @Override
    public Integer call() {
        List<String> args = new ArrayList<>(List.of("--port=" + udp.port, "--bind=" + udp.bind,
                "--robot-port=" + udp.robotPort));
        if (layouts != null) {
            args.add("--layouts=" + layouts);
        }
        if (demo) {
            args.add("--demo");
        }
        if (light) {
            args.add("--light");
        }
        javafx.application.Application.launch(TouchlineApp.class, args.toArray(String[]::new));
        return 0;
    }
}
