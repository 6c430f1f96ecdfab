package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.layout.FlowPane;
import javafx.util.StringConverter;
import touchline.record.TimelineEvent;

import java.util.List;

/**
 * The replay's transport: play/pause, the speed, a button per kind of timeline event ("next
 * goal", in the event's colour), loop A, loop B, clear loop and the loop's line. It wraps on a
 * narrow window, so the file row above keeps its Open button in view.
 */
final class TransportBar {

    static final List<Double> SPEEDS = List.of(0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 10.0, 25.0, 50.0);

    private final Button play = new Button("▶ Play");
    private final ComboBox<Double> speed = new ComboBox<>();
    private final Label loop = new Label();
    private final List<Node> controls;
    private final FlowPane pane;

    TransportBar(ReplayViewModel model) {
        play.setId("replay-play");
        play.setOnAction(e -> model.playOrPause(speed.getValue()));
        play.setMinWidth(80);
        speed.setId("replay-speed");
        speed.getItems().setAll(SPEEDS);
        speed.setValue(1.0);
        speed.setConverter(new StringConverter<>() {
            @Override
            public String toString(Double d) {
                return d == null ? "" : ReplayViewModel.speedText(d);
            }

            @Override
            public Double fromString(String s) {
                return Double.parseDouble(s.replace("×", "").trim());
            }
        });
        speed.setOnAction(e -> model.setSpeed(speed.getValue()));
        Button goal = next(model, "replay-next-goal", "Next goal", TimelineEvent.Type.GOAL, "#d4a72c");
        Button change = next(model, "replay-next-state", "Next state change", TimelineEvent.Type.STATE_CHANGE, "#2f81f7");
        Button lost = next(model, "replay-next-lost", "Next robot lost", TimelineEvent.Type.ROBOT_LOST, "#cf222e");
        Button penalty = next(model, "replay-next-penalty", "Next penalty", TimelineEvent.Type.PENALTY, "#e16f24");
        Button a = ReplayView.button("replay-loop-a", "Loop A", model::markA);
        Button b = ReplayView.button("replay-loop-b", "Loop B", model::markB);
        Button clear = ReplayView.button("replay-loop-clear", "Clear loop", model::clearLoop);
        pane = new FlowPane(8, 6, play, new Label("Speed"), speed, goal, change, penalty, lost, a, b, clear, loop);
        pane.setStyle("-fx-alignment: center-left;");
        controls = List.of(play, speed, goal, change, penalty, lost, a, b, clear);
    }

    private static Button next(ReplayViewModel model, String id, String text, TimelineEvent.Type type, String colour) {
        Button b = ReplayView.button(id, text, () -> model.next(type));
        b.setStyle("-fx-border-color: " + colour + "; -fx-border-width: 0 0 3 0;");
        return b;
    }

    Node node() {
        return pane;
    }

    /** Without a replay the controls rest. */
    void enable(boolean replayOpen) {
        controls.forEach(n -> n.setDisable(!replayOpen));
    }

    /** Shows the play button's label and the loop's line as the model has them now. */
    void show(ReplayViewModel model) {
        ReplayView.setIfChanged(play, model.playLabel());
        ReplayView.setIfChanged(loop, model.loopText());
    }
}
