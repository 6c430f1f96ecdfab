package touchline.cli;

import javafx.embed.swing.SwingFXUtils;
import javafx.scene.image.WritableImage;
import javafx.stage.Stage;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.model.OptionState;
import touchline.transport.UdpConfig;
import touchline.ui.window.ConsoleWindow;
import touchline.ui.window.UiSettings;
import touchline.ui.window.LayoutNode;

import javax.imageio.ImageIO;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Renders a PNG of each main view against three simulated robots into docs/screenshots (run it
 * under {@code xvfb-run -a} on a machine without a screen): the demo layout, then each view
 * filling the window.
 */
@Command(name = "screenshots", mixinStandardHelpOptions = true,
        description = "Render a PNG of each main view against simulated robots (use xvfb-run without a screen).")
final class ScreenshotsCommand implements java.util.concurrent.Callable<Integer> {

    @Option(names = "--out", defaultValue = "docs/screenshots", description = "output directory (default ${DEFAULT-VALUE})")
    Path out;

    @Option(names = "--light", description = "light theme")
    boolean light;

    @Option(names = "--views", split = ",", description = "only these views (IDs, plus 'shortcuts' for the "
            + "shortcut sheet), without the demo layout, NAO, GameController and quick-open shots")
    List<String> only;

    /** view ID -> the robot-1 option it shows ("" for views without a source). */
    static final Map<String, String> SHOTS = new java.util.LinkedHashMap<>();

    static {
        SHOTS.put("robots", "");
        SHOTS.put("options", "");
        SHOTS.put("debug-console", "");
        SHOTS.put("network", "");
        SHOTS.put("regions", "havimo.region");
        SHOTS.put("plot", "demo.plotter");
        SHOTS.put("table", "demo.table");
        SHOTS.put("relative", "demo.relative");
        SHOTS.put("field", "demo.field");
        SHOTS.put("image", "demo.image");
        SHOTS.put("text", "demo.text");
        SHOTS.put("field-plot", "");
        SHOTS.put("viewers", "");
    }

    @Override
    public Integer call() throws Exception {
        Files.createDirectories(out);
        try (Console console = new Console(ConsoleConfig.defaults().withUdp(
                UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
             SimulatedTeam team = SimulatedTeam.start(3, console.field().port(), List.of())) {
            FxThread.startToolkit();
            Path layouts = Files.createTempDirectory("touchline-layouts");
            ConsoleWindow window = FxThread.call(() -> new ConsoleWindow(console,
                    new UiSettings(layouts, !light, true)).show(new Stage()));
            if (!FxThread.await(() -> console.field().robots().robots().size() >= 3
                    && console.field().options().options(1).listReceived(), 20_000)) {
                System.err.println("the simulated robots did not show up");
                return 1;
            }
            for (String option : SHOTS.values()) {
                if (!option.isEmpty()) {
                    console.optionSwitches().set(1, option, true);
                }
            }
            FxThread.await(() -> SHOTS.values().stream().filter(o -> !o.isEmpty()).allMatch(o ->
                    console.field().options().options(1).option(o).map(OptionState::streaming).orElse(false)), 10_000);
            Thread.sleep(3000); // let plots and logs fill
            if (only != null) {
                shootOnly(window);
                FxThread.run(() -> javafx.application.Platform.exit());
                return 0;
            }
            shoot(window, "demo-layout");
            for (Map.Entry<String, String> s : SHOTS.entrySet()) {
                shootView(window, s.getKey(), s.getValue());
            }
            shootNao(console.field(), window);
            shootGameController(console.field(), console.referee(), window);
            FxThread.run(() -> window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("robots", ""))))));
            FxThread.run(() -> window.quickOpen());
            Thread.sleep(800);
            FxThread.run(() -> {
                for (javafx.stage.Window w : List.copyOf(javafx.stage.Window.getWindows())) {
                    if (w instanceof Stage st && "Open view".equals(st.getTitle())) {
                        write(st.getScene().snapshot(null), "quick-open");
                        st.close();
                    }
                }
            });
            FxThread.run(() -> javafx.application.Platform.exit());
        }
        return 0;
    }

    /** One view filling the window, showing robot 1's {@code option} ("" for views without a source). */
    private void shootView(ConsoleWindow window, String view, String option) throws Exception {
        String source = option.isEmpty() ? "" : "1/" + option;
        FxThread.run(() -> window.shell().restore(List.of(new LayoutNode.Leaf(0,
                List.of(new LayoutNode.Entry(view, source))))));
        Thread.sleep(1500);
        if (view.equals("network")) {
            FxThread.run(() -> selectNewestStatus(window));
            Thread.sleep(300);
        }
        if (view.equals("field-plot")) {
            plotFields(window);
        }
        if (view.equals("viewers")) { // serving (View → Serve to viewers), so the view shows its URL
            FxThread.run(() -> ((javafx.scene.control.MenuBar) ((javafx.scene.layout.BorderPane) window.scene().getRoot())
                    .getTop()).getMenus().stream().flatMap(m -> m.getItems().stream())
                    .filter(i -> "menu-serve".equals(i.getId())).findFirst().ifPresent(javafx.scene.control.MenuItem::fire));
            Thread.sleep(1000);
        }
        if (view.equals("debug-console")) { // the search's highlighted matches
            FxThread.run(() -> ((javafx.scene.control.TextField) window.scene().lookup("#debug-search")).setText("ball lost"));
            Thread.sleep(500);
        }
        shoot(window, view);
    }

    /** The views asked for with --views, each filling the window, and the shortcut sheet if asked. */
    private void shootOnly(ConsoleWindow window) throws Exception {
        for (Map.Entry<String, String> s : SHOTS.entrySet()) {
            if (only.contains(s.getKey())) {
                shootView(window, s.getKey(), s.getValue());
            }
        }
        if (only.contains("shortcuts")) {
            Stage sheet = FxThread.call(window::shortcutSheet);
            Thread.sleep(800);
            FxThread.run(() -> {
                write(sheet.getScene().snapshot(null), "shortcuts");
                sheet.close();
            });
            System.out.println("wrote " + out.resolve("shortcuts.png"));
        }
    }

    /** Plot fields: each robot's x position and robot 1's battery, typed as a user would. */
    private static void plotFields(ConsoleWindow window) throws Exception {
        FxThread.run(() -> window.shell().openViews().stream().map(v -> v.view())
                .filter(v -> v instanceof touchline.ui.plots.FieldPlotView).findFirst().ifPresent(v -> {
                    touchline.model.store.FieldPlot f = ((touchline.ui.plots.FieldPlotView) v).fields();
                    for (int robot = 1; robot <= 3; robot++) {
                        f.add(robot, "status:robotPosition.x");
                    }
                    ((javafx.scene.control.TextField) window.scene().lookup("#field-path")).setText("robotPosition");
                }));
        Thread.sleep(4000);
    }

    /** Connects the NAO tab to a simulated NAO (touchline-nao-sim), discovers methods, shows the camera. */
    private void shootNao(touchline.app.LiveField field, ConsoleWindow window) throws Exception {
        RobotSideBinaries binaries = new RobotSideBinaries();
        if (binaries.missing("touchline-nao-sim").isPresent()) {
            System.err.println("no NAO screenshot: " + binaries.missing("touchline-nao-sim").get());
            return;
        }
        java.nio.file.Path sim = binaries.of("touchline-nao-sim");
        // the NAO tab as every user sees it: the link encrypted with CURVE keys (made for the shot)
        java.nio.file.Path keys = Files.createTempDirectory("touchline-shot-keys");
        new touchline.security.KeyDir(keys).create(true, new java.security.SecureRandom(),
                java.time.Instant.EPOCH.plus(field.clock().nowMicros(), java.time.temporal.ChronoUnit.MICROS));
        Process nao = new ProcessBuilder(sim.toString(), "--rpc-port", "0", "--cam-port", "0", "--curve-secret",
                keys.resolve("nao-server.secret").toString(), "--curve-clients", keys.resolve("console.public").toString())
                .redirectErrorStream(true).start();
        try {
            java.io.BufferedReader lines = new java.io.BufferedReader(new java.io.InputStreamReader(nao.getInputStream()));
            String rpc = lines.readLine().replaceAll("\\D+", "");
            String cam = lines.readLine().replaceAll("\\D+", "");
            FxThread.run(() -> window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("nao", ""))))));
            Thread.sleep(800);
            FxThread.run(() -> {
                javafx.scene.Scene scene = window.scene();
                ((javafx.scene.control.TextField) scene.lookup("#nao-rpc-port")).setText(rpc);
                ((javafx.scene.control.TextField) scene.lookup("#nao-cam-port")).setText(cam);
                ((javafx.scene.control.TextField) scene.lookup("#nao-keys")).setText(keys.toString());
                ((javafx.scene.control.ToggleButton) scene.lookup("#nao-connect")).fire();
            });
            Thread.sleep(1500);
            FxThread.run(() -> {
                javafx.scene.Scene scene = window.scene();
                javafx.scene.Node discover = scene.lookup("#nao-discover");
                if (discover instanceof javafx.scene.control.Button b) {
                    b.fire();
                }
                javafx.scene.control.ToggleButton camera = (javafx.scene.control.ToggleButton) scene.lookup("#nao-camera");
                if (!camera.isSelected()) {
                    camera.fire();
                }
            });
            Thread.sleep(2500);
            shoot(window, "nao");
            FxThread.run(() -> ((javafx.scene.control.ToggleButton) window.scene().lookup("#nao-connect")).fire());
        } finally {
            nao.destroy();
        }
    }

    /** Referees the simulated team for a moment (the robots follow) and shows the GameController tab. */
    private void shootGameController(touchline.app.LiveField field, touchline.app.Referee referee, ConsoleWindow window) throws Exception {
        List<java.net.InetSocketAddress> robots = field.robots().robots().stream()
                .map(touchline.model.RobotSnapshot::address).filter(java.util.Objects::nonNull).toList();
        touchline.transport.gamecontroller.GcConfig defaults = touchline.transport.gamecontroller.GcConfig.defaults(
                touchline.transport.gamecontroller.GcProfile.HL12);
        touchline.transport.gamecontroller.GcConfig config = new touchline.transport.gamecontroller.GcConfig(
                touchline.transport.gamecontroller.GcProfile.HL12, false, robots, null,
                new java.net.InetSocketAddress("127.0.0.1", 0), null, defaults.intervalMs(), true); // as the tab does
        touchline.game.Game game = new touchline.game.Game(touchline.game.LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0,
                referee.gameClock());
        touchline.app.game.GameRuntime owner = referee.start(game, config).runtime();
        owner.perform(new touchline.game.ToReady());
        owner.perform(new touchline.game.ToSet());
        owner.perform(new touchline.game.ToPlaying());
        FxThread.run(() -> window.shell().restore(List.of(new LayoutNode.Leaf(0,
                List.of(new LayoutNode.Entry("gamecontroller", ""))))));
        Thread.sleep(2500); // the robots hear PLAYING and report it; match mode shows its notice
        shoot(window, "gamecontroller");
        owner.perform(new touchline.game.ToFinished()); // robots hear FINISHED: the console may talk again
        Thread.sleep(1500);
        referee.stop();
    }

    /** Shows a keep-alive decoded and as hex in the network console's detail panes. */
    @SuppressWarnings("unchecked")
    private static void selectNewestStatus(ConsoleWindow window) {
        javafx.scene.control.TableView<touchline.transport.Envelope> table =
                (javafx.scene.control.TableView<touchline.transport.Envelope>) window.scene().lookup("#network-table");
        for (int i = table.getItems().size() - 1; i >= 0; i--) {
            if (table.getItems().get(i).kind().equals("status")) {
                table.getSelectionModel().select(i);
                table.scrollTo(Math.max(0, i - 10));
                return;
            }
        }
    }

    private void shoot(ConsoleWindow window, String name) throws Exception {
        FxThread.run(() -> write(window.scene().snapshot(null), name));
        System.out.println("wrote " + out.resolve(name + ".png"));
    }

    private void write(WritableImage image, String name) {
        try {
            ImageIO.write(SwingFXUtils.fromFXImage(image, null), "png", out.resolve(name + ".png").toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
