package touchline.ui.ros2;

import touchline.ui.window.ConsoleWindowFixture;
import touchline.ui.frame.ViewSource;

import javafx.scene.control.Button;
import javafx.scene.control.Labeled;
import javafx.scene.control.TextInputControl;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.bridges.BridgeAddress;
import touchline.testing.SimulatedRos2Robot;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The ROS 2 publish & call view on a simulated ROS 2 robot: a JSON message published from the
 * window arrives, a message of a type the robot advertises goes as CDR and the robot reads it,
 * and the robot's answers to service calls (JSON, CDR decoded, a failure) appear in the view.
 */
@Tag("ui")
@Tag("interop")
class RosCommandsUiTest {

    @TempDir
    Path layouts;

    @Test
    void aMessagePublishedFromTheWindowReachesTheRobotAndAServiceCallIsSent() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1", "--game-state", "INITIAL");
             ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            ui.console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            ui.fxRun(() -> ui.window.shell().restore(List.of()));
            ui.fxRun(() -> ui.window.open("ros-commands", ViewSource.NONE));
            RosCommandsView view = ui.view(RosCommandsView.class);
            Node status = new Node(view);
            ui.fxRun(() -> {
                ((TextInputControl) view.node().lookup("#ros-topic")).setText("/say");
                ((TextInputControl) view.node().lookup("#ros-type")).setText("std_msgs/msg/String");
                ((TextInputControl) view.node().lookup("#ros-json")).setText("{\"data\":\"from the window\"}");
            });
            ui.await(30, () -> {
                ((Button) view.node().lookup("#ros-publish")).fire();
                return status.text().equals("booster-1 publish on /say: sent");
            });
            ui.await(30, () -> robot.heard().contains("{\"data\":\"from the window\"}"));

            ui.fxRun(() -> ((TextInputControl) view.node().lookup("#ros-service")).setText("/booster-1/say"));
            // the bridge advertises its services after its channels: called again until it offers this one
            ui.await(30, () -> {
                ((Button) view.node().lookup("#ros-call")).fire();
                return !status.text().endsWith("offers no service /booster-1/say");
            });
            assertEquals("booster-1 call /booster-1/say: sent", ui.fx(status::text));
            ui.await(30, () -> status.answers().contains("/booster-1/say #1: {\"success\": true, \"message\": \"said\"}"));

            ui.fxRun(() -> {
                ((TextInputControl) view.node().lookup("#ros-service")).setText("/booster-1/check");
                ((TextInputControl) view.node().lookup("#ros-json")).setText("{}");
                ((Button) view.node().lookup("#ros-call")).fire();
                ((TextInputControl) view.node().lookup("#ros-service")).setText("/booster-1/kick");
                ((Button) view.node().lookup("#ros-call")).fire();
            });
            ui.await(30, () -> status.answers().contains("/booster-1/check #2: {success: true, message: \"all joints ready\"}")
                    && status.answers().contains("/booster-1/kick #3 failed: ")
                    && status.answers().contains("no ball in reach"));

            ui.fxRun(() -> {
                ((TextInputControl) view.node().lookup("#ros-topic")).setText("/goal_pose");
                ((TextInputControl) view.node().lookup("#ros-type")).setText("geometry_msgs/msg/PoseStamped");
                ((TextInputControl) view.node().lookup("#ros-json")).setText("{\"pose\":{\"position\":{\"x\":2.5}}}");
                ((Button) view.node().lookup("#ros-publish")).fire();
            });
            assertEquals("booster-1 publish on /goal_pose: sent", ui.fx(status::text));
            ui.await(30, () -> robot.heard().contains("\"position\": {\"x\": 2.5, \"y\": 0.0, \"z\": 0.0}"));
            assertTrue(robot.heard().contains("client advertised /goal_pose (cdr)"), robot.heard());
        }
    }

    private record Node(RosCommandsView view) {
        String text() {
            return ((Labeled) view.node().lookup("#ros-status")).getText();
        }

        String answers() {
            return ((TextInputControl) view.node().lookup("#ros-answers")).getText();
        }
    }
}
