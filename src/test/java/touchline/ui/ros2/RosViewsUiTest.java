package touchline.ui.ros2;

import touchline.ui.window.ConsoleWindowFixture;
import touchline.ui.frame.View;
import touchline.ui.frame.ViewSource;

import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.TableView;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.bridges.BridgeAddress;
import touchline.testing.SimulatedRos2Robot;
import touchline.ui.field.FieldView;
import touchline.ui.plots.ImageDataView;
import touchline.ui.consoles.TableDataView;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A simulated ROS 2 robot's camera, joints and markers in the views small robots' data uses: its
 * topics are sources there, its JPEG is shown in the image view, its 24 joints in the table view,
 * its markers on the field, and its temperature in the Robots table.
 */
@Tag("ui")
@Tag("interop")
class RosViewsUiTest {

    @TempDir
    Path layouts;

    private static String status(View v) {
        return ((Label) v.node().lookup(".source-status")).getText();
    }

    @Test
    void theBridgedRobotsTopicsAreSourcesOfTheImageTableAndFieldViews() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1", "--game-state", "INITIAL");
             ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            int id = ui.console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            ui.fxRun(() -> ui.window.shell().restore(List.of()));
            ui.fxRun(() -> ui.window.open("image", ViewSource.NONE));
            ImageDataView image = ui.view(ImageDataView.class);
            ui.await(30, () -> status(image).startsWith("64×48 JPEG"));
            @SuppressWarnings("unchecked")
            ComboBox<ViewSource> choice = (ComboBox<ViewSource>) image.node().lookup(".combo-box");
            assertEquals(new ViewSource(id, "/camera/image/compressed"), ui.fx(choice::getValue), "chosen by itself");

            ui.fxRun(() -> ui.window.open("table", new ViewSource(id, "/joint_states")));
            TableDataView table = ui.view(TableDataView.class);
            TableView<?> joints = (TableView<?>) table.node().lookup("#data-table");
            ui.await(30, () -> joints.getItems().size() == 24);
            // the next joint states change the cells of the rows there are; the rows stay (set afresh, each
            // message re-styled and laid out every cell of the table)
            Object firstRow = ui.fx(() -> joints.getItems().get(0));
            String position = ui.fx(() -> joints.getColumns().get(1).getCellData(0).toString());
            ui.await(30, () -> !position.equals(String.valueOf(joints.getColumns().get(1).getCellData(0))));
            assertSame(firstRow, ui.fx(() -> joints.getItems().get(0)), "the same row, its cells changed");

            ui.fxRun(() -> ui.window.open("field", new ViewSource(id, "/markers")));
            FieldView field = ui.view(FieldView.class);
            ui.await(30, () -> status(field).endsWith("4 objects from /markers"));

            ui.fxRun(() -> ui.window.open("robots", ViewSource.NONE));
            touchline.ui.robots.RobotsView robots = ui.view(touchline.ui.robots.RobotsView.class);
            ui.await(30, () -> robots.node().lookupAll(".table-cell").stream().anyMatch(n ->
                    n instanceof javafx.scene.control.Labeled l && l.getText() != null && l.getText().matches("4[0-3] °C")));
        }
    }
}
