package touchline.ui;

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

/**
 * The real console window on a headless (Monocle) stage, listening on a loopback port the OS
 * chose, for the UI tests.
 */
final class ConsoleWindowFixture implements AutoCloseable {

    final Console console;
    final ConsoleWindow window;
    final FxRobot robot = new FxRobot();

    ConsoleWindowFixture(Path layoutDir) throws Exception {
        console = new Console(ConsoleConfig.defaults().withUdp(
                UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
        Stage stage = FxToolkit.registerPrimaryStage();
        window = WaitForAsyncUtils.asyncFx(() -> new ConsoleWindow(console, new UiSettings(layoutDir, true, false))
                .show(stage)).get(30, TimeUnit.SECONDS);
        WaitForAsyncUtils.asyncFx(() -> {
            stage.toFront();
            stage.requestFocus();
        }).get(10, TimeUnit.SECONDS);
    }

    int port() {
        return console.udp().localPort();
    }

    <T> T fx(Callable<T> step) throws Exception {
        return WaitForAsyncUtils.asyncFx(step).get(30, TimeUnit.SECONDS);
    }

    void fxRun(Runnable step) throws Exception {
        fx(() -> {
            step.run();
            return null;
        });
    }

    /** Waits (polling on the FX thread) until the condition holds, failing after {@code seconds}. */
    void await(int seconds, Callable<Boolean> condition) throws Exception {
        WaitForAsyncUtils.waitFor(seconds, TimeUnit.SECONDS, () -> fx(condition));
    }

    /** The options tree's cell for one option, or null while it is not shown. */
    javafx.scene.control.TreeCell<touchline.ui.views.OptionsView.Row> optionCell(int robotId, String option) {
        return robot.lookup(".tree-cell").<javafx.scene.control.TreeCell<touchline.ui.views.OptionsView.Row>>queryAll()
                .stream().filter(c -> c.getItem() != null && c.getItem().option() != null
                        && (robotId < 0 || c.getItem().robotId() == robotId)
                        && c.getItem().option().name().equals(option)).findFirst().orElse(null);
    }

    /** Clicks an option in the tree and waits until it is selected and the tree has the keyboard. */
    void selectOption(int robotId, String option) throws Exception {
        await(15, () -> optionCell(robotId, option) != null);
        fxRun(() -> {
            window.scene().getWindow().requestFocus();
            robot.lookup("#options-tree").query().requestFocus();
        });
        robot.clickOn(fx(() -> optionCell(robotId, option)));
        await(10, () -> {
            var tree = robot.lookup("#options-tree").queryAs(javafx.scene.control.TreeView.class);
            var item = (javafx.scene.control.TreeItem<?>) tree.getSelectionModel().getSelectedItem();
            return item != null && item.getValue() instanceof touchline.ui.views.OptionsView.Row r && r.option() != null
                    && r.option().name().equals(option);
        });
    }

    <V extends View> V view(Class<V> type) throws Exception {
        return fx(() -> window.shell().openViews().stream().map(Shell.OpenView::view).filter(type::isInstance)
                .map(type::cast).findFirst().orElse(null));
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
