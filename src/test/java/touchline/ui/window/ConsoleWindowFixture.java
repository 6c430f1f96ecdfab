package touchline.ui.window;

import javafx.stage.Stage;
import org.testfx.api.FxRobot;
import org.testfx.api.FxToolkit;
import org.testfx.util.WaitForAsyncUtils;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.transport.UdpConfig;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import touchline.ui.frame.View;

/**
 * The real console window on a headless (Monocle) stage, listening on a loopback port the OS
 * chose, for the UI tests. A class tagged {@link touchline.testing.UiTest} gets one per field of
 * this type before each test; a test that opens its windows itself (another configuration, two
 * windows) uses the constructors.
 */
public final class ConsoleWindowFixture implements AutoCloseable {

    public final Console console;
    public final ConsoleWindow window;
    public final FxRobot robot = new FxRobot();

    public ConsoleWindowFixture(Path layoutDir) throws Exception {
        this(layoutDir, loopback());
    }

    /** The console on a loopback port the OS chose. */
    public static ConsoleConfig loopback() {
        return ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
    }

    private final Path layoutDir;

    /** Where this window keeps its layouts and settings. */
    public Path layoutDir() {
        return layoutDir;
    }

    /** Views open when {@link ConsoleWindow#show} returned (on the FX thread, before any later pulse). */
    final int viewsWhenShown;

    public ConsoleWindowFixture(Path layoutDir, ConsoleConfig config) throws Exception {
        this(layoutDir, config, false);
    }

    /** With {@code viewsAfterShown}: shown as {@code touchline console} shows it (views after the first frame). */
    public ConsoleWindowFixture(Path layoutDir, ConsoleConfig config, boolean viewsAfterShown) throws Exception {
        this.layoutDir = layoutDir;
        console = new Console(config).start();
        Stage stage = FxToolkit.registerPrimaryStage();
        int[] views = new int[1];
        window = WaitForAsyncUtils.asyncFx(() -> {
            ConsoleWindow w = new ConsoleWindow(console, new UiSettings(layoutDir, true, false)).show(stage, viewsAfterShown);
            views[0] = w.shell().openViews().size();
            return w;
        }).get(30, TimeUnit.SECONDS);
        viewsWhenShown = views[0];
        WaitForAsyncUtils.asyncFx(() -> {
            stage.toFront();
            stage.requestFocus();
        }).get(10, TimeUnit.SECONDS);
    }

    /** The window as on a 1280×720 laptop: 1280 × 650, a screen less a panel and the title bar. */
    public void laptopSize() throws Exception {
        fxRun(() -> {
            javafx.stage.Window w = window.scene().getWindow();
            w.setX(0);
            w.setY(0);
            w.setWidth(1280);
            w.setHeight(650);
        });
    }

    public int port() {
        return console.field().port();
    }

    public <T> T fx(Callable<T> step) throws Exception {
        return touchline.testing.FxStep.fx(step);
    }

    public void fxRun(Runnable step) throws Exception {
        fx(() -> {
            step.run();
            return null;
        });
    }

    /**
     * Waits (polling on the FX thread) until the condition holds, failing after {@code seconds}
     * but never sooner than {@link touchline.testing.Await#FLOOR_MILLIS}: a deadline only stops a
     * test that would hang; a loaded machine must not fail it.
     */
    public void await(int seconds, Callable<Boolean> condition) throws Exception {
        long millis = Math.max(seconds * 1000L, touchline.testing.Await.FLOOR_MILLIS);
        // A node a condition looks up may not be in the scene yet (a view's skin joins a pulse
        // later): that is "not yet", not a failure. The last such error is the timeout's cause.
        Exception[] last = {null};
        try {
            WaitForAsyncUtils.waitFor(millis, TimeUnit.MILLISECONDS, () -> {
                try {
                    return fx(condition);
                } catch (Exception e) {
                    last[0] = e;
                    return false;
                }
            });
        } catch (java.util.concurrent.TimeoutException e) {
            if (last[0] != null) {
                e.initCause(last[0]);
            }
            throw e;
        }
    }

    /** The options tree's cell for one option, or null while it is not shown. */
    javafx.scene.control.TreeCell<touchline.ui.options.OptionsView.Row> optionCell(int robotId, String option) {
        return robot.lookup(".tree-cell").<javafx.scene.control.TreeCell<touchline.ui.options.OptionsView.Row>>queryAll()
                .stream().filter(c -> c.getItem() != null && c.getItem().option() != null
                        && (robotId < 0 || c.getItem().robotId() == robotId)
                        && c.getItem().option().name().equals(option)).findFirst().orElse(null);
    }

    /**
     * Selects an option in the tree and gives the tree the keyboard, the way a user who walked
     * there with the arrow keys would have it. Not a mouse click at the cell's coordinates: the
     * tree rebuilds while robots report (a robot's label changes, e.g. going offline on a slow
     * machine), and a click aimed at a cell found a moment earlier could land on another row.
     * Waits until the window is focused, the tree owns the keyboard and the option is selected,
     * so a key typed next reaches the tree.
     */
    void selectOption(int robotId, String option) throws Exception {
        await(30, () -> optionItem(robotId, option) != null);
        fxRun(() -> {
            window.scene().getWindow().requestFocus();
            var tree = optionsTree();
            tree.getSelectionModel().select(optionItem(robotId, option));
            tree.requestFocus();
        });
        await(30, () -> {
            var tree = optionsTree();
            var item = tree.getSelectionModel().getSelectedItem();
            return window.scene().getWindow().isFocused() && window.scene().getFocusOwner() == tree
                    && item != null && item.getValue().option() != null
                    && item.getValue().robotId() == robotId && item.getValue().option().name().equals(option);
        });
    }

    @SuppressWarnings("unchecked")
    private javafx.scene.control.TreeView<touchline.ui.options.OptionsView.Row> optionsTree() {
        return robot.lookup("#options-tree").queryAs(javafx.scene.control.TreeView.class);
    }

    /** The options tree's item for one option, or null while the tree does not hold it. */
    private javafx.scene.control.TreeItem<touchline.ui.options.OptionsView.Row> optionItem(int robotId, String option) {
        var root = optionsTree().getRoot();
        for (var robotItem : root.getChildren()) {
            for (var item : robotItem.getChildren()) {
                var row = item.getValue();
                if (row.option() != null && row.robotId() == robotId && row.option().name().equals(option)) {
                    return item;
                }
            }
        }
        return null;
    }

    public <V extends View> V view(Class<V> type) throws Exception {
        return fx(() -> window.shell().openViews().stream().map(Shell.OpenView::view).filter(type::isInstance)
                .map(type::cast).findFirst().orElse(null));
    }

    /**
     * The points a plot shows, as its status line says them ("1 series · 3 points"); -1 before it
     * says (FX thread; the line changes at most twice a second).
     */
    public int plottedPoints(View plot) {
        String status = robot.from(plot.node()).lookup(".source-status").queryLabeled().getText();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(\\d+) points").matcher(status);
        return m.find() ? Integer.parseInt(m.group(1)) : -1;
    }

    /** The robots' shapes on a field view (FX thread): one per robot placed. */
    public int robotsOnTheField() {
        return ((javafx.scene.Parent) robot.lookup("#field-robots").query()).getChildrenUnmodifiable().size();
    }

    @Override
    public void close() throws Exception {
        fxRun(() -> {
            window.pulse().stop();
            window.scene().getWindow().hide();
        });
        FxToolkit.cleanupStages();
        console.close();
    }
}
