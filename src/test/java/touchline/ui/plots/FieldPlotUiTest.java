package touchline.ui.plots;

import javafx.scene.control.ListView;
import javafx.scene.input.KeyCode;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.RobotProcess;
import touchline.testing.UiTest;
import touchline.ui.window.LayoutNode;
import touchline.ui.plots.FieldPlotView;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import touchline.ui.window.ConsoleWindowFixture;

/**
 * Plot anything in the real window against the real simulated robot: a field path is found by
 * typing, Enter adds it as a series, the plot draws its points, and the plotted data exports
 * as CSV (time, one column per series).
 */
@UiTest
@Tag("integration")
class FieldPlotUiTest {

    private ConsoleWindowFixture ui;

    @Test
    @SuppressWarnings("unchecked")
    void aFieldPathTypedAndEnteredIsPlottedAndExportedAsCsv() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(5, ui.port()).start()) {
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("field-plot", ""))))));
            ui.await(15, () -> ui.robot.lookup("#field-paths").queryAs(ListView.class).getItems()
                    .contains("status:batteryPercent"));
            ui.fxRun(() -> {
                ui.window.scene().getWindow().requestFocus();
                ui.robot.lookup("#field-path").query().requestFocus();
            });
            ui.await(10, () -> ui.robot.lookup("#field-path").query().isFocused());
            ui.robot.write("batterypercent");
            ui.await(10, () -> ui.robot.lookup("#field-paths").queryAs(ListView.class).getItems()
                    .equals(List.of("status:batteryPercent")));
            ui.robot.type(KeyCode.ENTER);
            FieldPlotView view = ui.view(FieldPlotView.class);
            ui.await(10, () -> view.fields().series().size() == 1);
            assertEquals(5, view.fields().series().get(0).robotId());
            ui.await(10, () -> ui.robot.lookup("#field-status").queryLabeled().getText().matches("1 series · [1-9]\\d* points"));

            Path csv = ui.layoutDir().resolve("plot.csv");
            // Export CSV… asks in a dialog that is not modal: a modal one (or the native file chooser)
            // takes a maximised window out of its maximised state under openbox (issue 36 item 7)
            ui.robot.clickOn("#field-export");
            ui.await(10, () -> exportDialog() != null);
            ui.fxRun(() -> {
                javafx.scene.control.DialogPane pane = exportDialog();
                assertEquals(javafx.stage.Modality.NONE, ((javafx.stage.Stage) pane.getScene().getWindow()).getModality());
                ((javafx.scene.control.TextField) pane.lookup(".text-field")).setText(csv.toString());
                ((javafx.scene.control.Button) pane.lookupButton(javafx.scene.control.ButtonType.OK)).fire();
            });
            ui.await(10, () -> Files.exists(csv) && exportDialog() == null);
            List<String> lines = Files.readAllLines(csv);
            assertEquals("time_s,robot 5 status:batteryPercent", lines.get(0));
            assertTrue(lines.size() > 1 && lines.get(1).matches("\\d+\\.\\d{6},\\d+"), lines.toString());
            assertTrue(ui.robot.lookup("#field-note").queryLabeled().getText().startsWith("exported 1 series"));
        }
    }

    /** The Export CSV dialog while it is showing, else null. */
    private static javafx.scene.control.DialogPane exportDialog() {
        return javafx.stage.Window.getWindows().stream().filter(javafx.stage.Window::isShowing)
                .map(w -> w.getScene() == null ? null : w.getScene().getRoot())
                .filter(javafx.scene.control.DialogPane.class::isInstance).map(javafx.scene.control.DialogPane.class::cast)
                .findFirst().orElse(null);
    }
}
