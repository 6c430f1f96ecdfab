package touchline.ui;

import javafx.application.Application;
import javafx.stage.Stage;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.transport.UdpConfig;
import touchline.ui.window.LayoutStore;

import java.nio.file.Path;
import java.util.Map;
import touchline.ui.window.ConsoleWindow;
import touchline.ui.window.UiSettings;

/**
 * The JavaFX application: starts a {@link Console} from the command-line parameters
 * ({@code --port}, {@code --bind}, {@code --robot-port}, {@code --layouts}, {@code --light},
 * {@code --demo}) and shows the {@link ConsoleWindow}. Closing the window stops the console.
 */
public final class TouchlineApp extends Application {

    private Console console;

    /** As JavaFX's launcher makes it: the console starts in {@link #start}. */
    public TouchlineApp() {
    }

    /** Around a console already started (tests). */
    TouchlineApp(Console console) {
        this.console = console;
    }

    @Override
    public void start(Stage stage) throws Exception {
        Map<String, String> p = getParameters().getNamed();
        boolean demo = getParameters().getUnnamed().contains("--demo") || "true".equals(p.get("demo"));
        boolean light = getParameters().getUnnamed().contains("--light") || "true".equals(p.get("light"));
        UdpConfig udp = UdpConfig.defaults()
                .withListenPort(Integer.parseInt(p.getOrDefault("port", Integer.toString(UdpConfig.CONSOLE_PORT))))
                .withBindAddress(p.getOrDefault("bind", "0.0.0.0"))
                .withRobotPort(Integer.parseInt(p.getOrDefault("robot-port", "0")));
        console = new Console(ConsoleConfig.defaults().withUdp(udp)).start();
        Path layouts = p.containsKey("layouts") ? Path.of(p.get("layouts")) : LayoutStore.defaultDir();
        new ConsoleWindow(console, new UiSettings(layouts, !light, demo)).show(stage);
    }

    /**
     * JavaFX calls this on its own thread: the console's close (the recording finished, sockets
     * closed, threads joined) runs on a non-daemon {@code touchline-close} thread and this returns;
     * the JVM exits when that thread ends.
     */
    @Override
    public void stop() {
        Console c = console;
        if (c != null) {
            Thread closing = new Thread(c::close, "touchline-close");
            closing.setDaemon(false);
            closing.start();
        }
    }
}
