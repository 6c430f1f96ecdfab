package touchline.ui.ros2;

import javafx.collections.FXCollections;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.TextArea;
import javafx.scene.control.TextField;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import touchline.app.bridges.RosBridges;
import touchline.transport.SendResult;
import touchline.transport.remote.BridgeStatus;
import touchline.transport.remote.ServiceAnswer;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.util.List;

/**
 * A ROS 2 robot's topics and services from the window, beside its parameters: a message typed
 * as JSON published on a topic (when its bridge offers {@code clientPublish}; in CDR by the
 * type's definition when the robot takes CDR), or a service called with a request typed the
 * same way. Both pass the console's send gate like a parameter set: held during play (the
 * newest per topic goes out when play stops), refused on a viewing console; the status line
 * says which. The robot's answers to service calls (decoded responses, failures with their
 * reason) are listed below, newest last.
 */
public final class RosCommandsView implements View {

    /** One bridged robot as the robot choice lists it. */
    public record Target(int robotId, String name) {
        @Override
        public String toString() {
            return name + " (" + robotId + ")";
        }
    }

    private final RosBridges bridges;
    private final ComboBox<Target> robot = new ComboBox<>();
    private final TextField topic = new TextField();
    private final TextField type = new TextField();
    private final TextField service = new TextField();
    private final TextArea json = new TextArea("{\"data\": \"hello\"}");
    private final Label status = new Label();
    private final TextArea answers = new TextArea();
    private List<ServiceAnswer> shown = List.of();
    private final BorderPane root = new BorderPane();

    public RosCommandsView(ViewContext context) {
        this.bridges = context.bridges();
        robot.setId("ros-robot");
        robot.setPromptText("robot");
        topic.setId("ros-topic");
        topic.setPromptText("topic, e.g. /say");
        type.setId("ros-type");
        type.setPromptText("type, e.g. std_msgs/msg/String");
        service.setId("ros-service");
        service.setPromptText("service, e.g. /booster-1/say");
        json.setId("ros-json");
        json.setPrefRowCount(6);
        Button publish = new Button("Publish");
        publish.setId("ros-publish");
        publish.setOnAction(e -> send("publish on " + topic.getText().strip(), target() == null ? null
                : bridges.publish(target().robotId(), topic.getText().strip(), type.getText().strip(), json.getText())));
        Button call = new Button("Call");
        call.setId("ros-call");
        call.setOnAction(e -> send("call " + service.getText().strip(), target() == null ? null
                : bridges.callService(target().robotId(), service.getText().strip(), json.getText())));
        status.setId("ros-status");
        answers.setId("ros-answers");
        answers.setEditable(false);
        answers.setPrefRowCount(4);
        answers.setPromptText("the robot's answers to service calls");
        HBox publishRow = new HBox(8, new Label("Topic"), topic, type, publish);
        HBox callRow = new HBox(8, new Label("Service"), service, call);
        publishRow.setStyle("-fx-alignment: center-left;");
        callRow.setStyle("-fx-alignment: center-left;");
        VBox top = new VBox(6, new HBox(8, new Label("Robot"), robot), publishRow, callRow,
                new Label("Message / request (field values as JSON; sent as CDR when the robot takes it)"));
        top.setStyle("-fx-padding: 6 8 6 8;");
        root.setTop(top);
        root.setCenter(json);
        root.setBottom(new VBox(4, status, new Label("Service answers"), answers));
    }

    private Target target() {
        return robot.getValue();
    }

    private void send(String what, SendResult result) {
        status.setText(result == null ? "choose a robot first" : target().name() + " " + what + ": " + result.describe());
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        List<BridgeStatus> statuses = bridges.statuses();
        if (statuses.size() != robot.getItems().size()) {
            Target chosen = robot.getValue();
            robot.setItems(FXCollections.observableArrayList(statuses.stream()
                    .map(b -> new Target(b.robotId(), b.name())).toList()));
            robot.setValue(chosen != null ? chosen : robot.getItems().isEmpty() ? null : robot.getItems().get(0));
        }
        List<ServiceAnswer> now = target() == null ? List.of() : bridges.serviceAnswers(target().robotId());
        if (!now.equals(shown)) {
            shown = now;
            answers.setText(String.join("\n", now.stream().map(ServiceAnswer::describe).toList()));
            answers.positionCaret(answers.getLength());
        }
    }
}
