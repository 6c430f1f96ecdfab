package touchline.ui.ros2;

import touchline.ui.window.ConsoleWindowFixture;
import touchline.ui.frame.ViewSource;

import javafx.scene.control.Button;
import javafx.scene.control.Labeled;
import javafx.scene.control.TableView;
import javafx.scene.input.KeyCode;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.bridges.BridgeAddress;
import touchline.testing.SimulatedRos2Robot;
import touchline.testing.UiTest;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The Parameters view on a simulated ROS 2 robot (the Python Foxglove SDK): Refresh lists its
 * parameters, Space on a bool switches it at the robot, the status line says it was sent.
 */
@UiTest
@Tag("interop")
class ParametersUiTest {

    private ConsoleWindowFixture ui;

    @Test
    void refreshListsTheRobotsParametersAndSpaceTogglesABool() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1", "--game-state", "INITIAL")) {
            ui.console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            ui.fxRun(() -> ui.window.shell().restore(List.of()));
            ui.fxRun(() -> ui.window.open("parameters", ViewSource.NONE));
            ParametersView view = ui.view(ParametersView.class);
            @SuppressWarnings("unchecked")
            TableView<ParametersView.Row> table = (TableView<ParametersView.Row>) view.node().lookup("#parameters-table");
            ui.await(30, () -> {
                ((Button) view.node().lookup("#parameters-refresh")).fire();
                return table.getItems().size() == 3;
            });
            ui.fxRun(() -> {
                int row = 0;
                while (!table.getItems().get(row).name().equals("debug.draw_ball")) {
                    row++;
                }
                table.getSelectionModel().select(row);
                table.requestFocus();
            });
            assertEquals(false, ui.fx(() -> table.getSelectionModel().getSelectedItem().value()));
            ui.robot.press(KeyCode.SPACE).release(KeyCode.SPACE);
            ui.await(30, () -> ((Labeled) view.node().lookup("#parameters-status")).getText()
                    .equals("booster-1 debug.draw_ball = true: sent"));
            ui.await(30, () -> robot.heard().contains("parameter debug.draw_ball set to true"));
        }
    }
}
