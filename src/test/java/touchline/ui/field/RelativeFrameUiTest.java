package touchline.ui.field;

import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.bridges.BridgeAddress;
import touchline.proto.Drawing;
import touchline.testing.SimulatedRos2Robot;
import touchline.testing.UiTest;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ConsoleWindowFixture;
import touchline.ui.window.LayoutNode;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A ROS 2 robot's surroundings in its own frame: booster-1 stands at (1, 0.5) of map looking along map's
 * y (its tree map→odom→base_link→camera, odom drifted to (0.5, -0.25) turned a quarter), booster-2 at
 * (2, 0.5). Its ball marker, in map at (1.8, 0.25), is 0.25 m behind and 0.8 m right of base_link, and
 * booster-2 is 1 m to its right; choosing camera (0.05 m ahead of base_link) moves the ball 0.05 m further
 * back, and the layout keeps the choice.
 */
@UiTest
@Tag("interop")
class RelativeFrameUiTest {

    private ConsoleWindowFixture ui;

    /** The first circle (the ball) where the view placed it, or null. */
    private static Drawing.FieldShape ball(RelativePositionsView v) {
        Drawing.FieldDrawing d = v.centred().picture().markers();
        return d == null ? null : d.getShapesList().stream()
                .filter(s -> s.getForm() == Drawing.FieldShape.Form.CIRCLE).findFirst().orElse(null);
    }

    private static boolean ballAt(RelativePositionsView v, double x, double y) {
        Drawing.FieldShape s = ball(v);
        return s != null && Math.abs(s.getXy(0) - x) < 1 && Math.abs(s.getXy(1) - y) < 1;
    }

    private static boolean robotAt(RelativePositionsView v, int id, double x, double y) {
        return v.centred().picture().robots().stream().anyMatch(p -> p.robot().id() == id
                && Math.abs(p.x() - x) < 1 && Math.abs(p.y() - y) < 1);
    }

    @Test
    @SuppressWarnings("unchecked")
    void theBallInMapIsWhereTheRobotsTreePutsItInItsOwnFrame() throws Exception {
        String facingY = String.valueOf(Math.PI / 2);
        try (SimulatedRos2Robot one = new SimulatedRos2Robot("booster-1", "--radius", "0", "--centre", "1,0.5",
                "--heading", facingY, "--odom", "0.5,-0.25," + Math.PI / 2);
             SimulatedRos2Robot two = new SimulatedRos2Robot("booster-2", "--radius", "0", "--centre", "2,0.5",
                     "--heading", facingY)) {
            int id = ui.console.bridges().connect(BridgeAddress.parse("booster-1=" + one.url()), null);
            int other = ui.console.bridges().connect(BridgeAddress.parse("booster-2=" + two.url()), null);
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("relative", new ViewSource(id, "/markers").encode()))))));
            RelativePositionsView view = ui.view(RelativePositionsView.class);
            ui.await(30, () -> ballAt(view, -250, -800) && robotAt(view, other, 0, -1000));
            assertEquals("base_link", ui.fx(() -> view.centred().picture().frame()), "automatic is base_link");
            ui.await(10, () -> ((Label) view.node().lookup(".source-status")).getText().startsWith("1 robots in base_link"));

            ComboBox<String> frame = ui.robot.lookup("#relative-frame").queryAs(ComboBox.class);
            ui.await(10, () -> frame.getItems().contains("camera"));
            ui.fxRun(() -> frame.setValue("camera"));
            ui.await(10, () -> ballAt(view, -300, -800) && robotAt(view, other, -50, -1000));

            List<LayoutNode> saved = ui.fx(() -> ui.window.shell().capture());
            ui.fxRun(() -> ui.window.shell().restore(saved));
            RelativePositionsView again = ui.view(RelativePositionsView.class);
            assertEquals("camera", ui.fx(() -> again.centred().chosen()), "kept with the layout");
            assertEquals(new ViewSource(id, "/markers"), ui.fx(again::source));
            ui.await(10, () -> ballAt(again, -300, -800));
        }
    }

    /** A small robot's relative positions are drawn as before: its objects, and no frame to choose. */
    @Test
    @Tag("integration")
    void aSmallRobotsObjectsAreDrawnAsBeforeWithoutAFrame() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (touchline.testing.RobotProcess robot = touchline.testing.RobotProcess.robot(3, ui.port()).start()) {
            ui.await(15, () -> ui.console.field().options().options(3).option("demo.relative").isPresent());
            ui.console.optionSwitches().set(3, "demo.relative", true);
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("relative", new ViewSource(3, "demo.relative").encode()))))));
            RelativePositionsView view = ui.view(RelativePositionsView.class);
            ui.await(15, () -> ((Label) view.node().lookup(".source-status")).getText().matches("\\d+ objects.*"));
            assertFalse(ui.fx(() -> view.node().lookup("#relative-frame").isVisible()), "no frame for a small robot");
        }
    }
}
