package touchline.ui.field;

import javafx.scene.Node;
import javafx.scene.canvas.Canvas;
import javafx.scene.control.ComboBox;
import javafx.scene.input.KeyCode;
import javafx.scene.layout.Pane;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.bridges.BridgeAddress;
import touchline.model.FramedField;
import touchline.testing.SimulatedRos2Robot;
import touchline.testing.UiTest;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ConsoleWindowFixture;
import touchline.ui.window.LayoutNode;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A ROS 2 robot on the field in the frame chosen there: the simulated robot stands at (1, 0.5) of
 * map, its odometry frame lies at (0.5, -0.25) of map turned a quarter (its TF tree:
 * map→odom→base_link→camera); automatic draws it in map, choosing odom with the keyboard draws it
 * where odom's transform puts it, and the layout keeps the choice.
 */
@UiTest
@Tag("interop")
class FieldFrameUiTest {

    private ConsoleWindowFixture ui;

    private static FramedField.Placed placed(FieldView v, int id) {
        return v.frames().picture().robots().stream().filter(p -> p.robot().id() == id).findFirst().orElse(null);
    }

    private static boolean at(FieldView v, int id, double x, double y) {
        FramedField.Placed p = placed(v, id);
        return p != null && Math.abs(p.x() - x) < 1 && Math.abs(p.y() - y) < 1;
    }

    @Test
    @SuppressWarnings("unchecked")
    void choosingOdomDrawsTheRobotWhereTheTransformPutsIt() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1", "--radius", "0", "--centre", "1,0.5",
                "--odom", "0.5,-0.25," + Math.PI / 2)) {
            int id = ui.console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("field", new ViewSource(id, "/markers").encode()))))));
            FieldView field = ui.view(FieldView.class);
            ui.await(30, () -> at(field, id, 1000, 500) && field.frames().frames().contains("odom"));
            assertEquals("map", ui.fx(() -> field.frames().picture().frame()), "automatic is map");

            ComboBox<String> frame = ui.robot.lookup("#field-frame").queryAs(ComboBox.class);
            ui.fxRun(() -> {
                ui.window.scene().getWindow().requestFocus();
                frame.requestFocus();
            });
            ui.await(10, () -> frame.isFocused());
            for (int i = 0; i < 10 && !"odom".equals(ui.fx(frame::getValue)); i++) {
                ui.robot.type(KeyCode.DOWN);
            }
            assertEquals("odom", ui.fx(frame::getValue));
            // (1, 0.5) of map is (0.5, 0.75) from odom's origin: a quarter turn back puts it at (0.75, -0.5)
            ui.await(10, () -> at(field, id, 750, -500));
            ui.await(10, () -> {
                Canvas canvas = ((touchline.ui.render.ResizableCanvas) field.node().lookup("#field-canvas")).canvas();
                double scale = Math.min(canvas.getWidth() / (FieldView.FIELD_LENGTH + 2 * FieldView.BORDER),
                        canvas.getHeight() / (FieldView.FIELD_WIDTH + 2 * FieldView.BORDER));
                Node mark = ((Pane) field.node().lookup("#field-robots")).getChildren().get(0);
                return Math.abs(mark.getLayoutX() - (canvas.getWidth() / 2 + 750 * scale)) < 1
                        && Math.abs(mark.getLayoutY() - (canvas.getHeight() / 2 + 500 * scale)) < 1;
            });
            ui.await(10, () -> ((javafx.scene.control.Label) field.node().lookup(".source-status")).getText()
                    .startsWith("1 robots in odom"));

            List<LayoutNode> saved = ui.fx(() -> ui.window.shell().capture());
            ui.fxRun(() -> ui.window.shell().restore(saved));
            FieldView again = ui.view(FieldView.class);
            assertEquals("odom", ui.fx(() -> again.frames().chosen()), "kept with the layout");
            assertEquals(new ViewSource(id, "/markers"), ui.fx(again::source));
            ui.await(10, () -> at(again, id, 750, -500));
        }
    }
}
