package touchline.ui.frame;

import javafx.collections.FXCollections;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.layout.HBox;
import touchline.model.OptionState;
import touchline.model.RobotOptions;
import touchline.model.RobotSnapshot;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import touchline.app.LiveField;

/**
 * The bar on top of a visualisation: which robot's option it shows, chosen from the options
 * of the kinds it can draw, plus a status line (e.g. "waiting for data", "3 NaN skipped").
 * A source from a saved layout stays selected even while its robot is absent.
 */
public final class SourceBar extends HBox {

    private final LiveField field;
    private final Set<Integer> kinds;
    private final Set<Integer> rosKinds;
    private final ComboBox<ViewSource> choice = new ComboBox<>();
    private final Label status = new Label();
    private final PacedText paced = new PacedText();
    private long seenOptionsVersion = -1;
    private long seenRobotsVersion = -1;
    private long readMicros = Long.MIN_VALUE;

    /** The least time between two reads caused by the robot registry alone. */
    public static final long REREAD_MICROS = 500_000;

    /** Lists the robots' options of {@code kinds} and the ROS 2 robots' topics shown as data of {@code rosKinds}. */
    SourceBar(LiveField field, Set<Integer> kinds, Set<Integer> rosKinds, ViewSource initial) {
        super(8);
        this.field = field;
        this.kinds = kinds;
        this.rosKinds = rosKinds;
        getStyleClass().add("source-bar");
        choice.setPromptText("choose robot · option");
        choice.setPrefWidth(260);
        if (initial != null && initial.isSet()) {
            choice.getItems().add(initial);
            choice.getSelectionModel().select(initial);
        }
        status.getStyleClass().add("source-status");
        Label label = new Label("Source");
        label.setMinWidth(javafx.scene.layout.Region.USE_PREF_SIZE);
        choice.setMinWidth(160);
        getChildren().addAll(label, choice, status);
        setStyle("-fx-padding: 4 8 4 8; -fx-alignment: center-left;");
    }

    /** Puts a view's own controls (e.g. the field's frame) after the source, before the status. */
    public void add(javafx.scene.Node... controls) {
        getChildren().addAll(getChildren().indexOf(status), List.of(controls));
    }

    /** Selects {@code source} (a saved layout's), listed even while its robot is absent. */
    public void select(ViewSource source) {
        if (source.isSet()) {
            if (!choice.getItems().contains(source)) {
                choice.getItems().add(source);
            }
            choice.getSelectionModel().select(source);
        }
    }

    public ViewSource selected() {
        ViewSource s = choice.getValue();
        return s == null ? ViewSource.NONE : s;
    }

    /** The status line as it should read now; it changes at most twice a second ({@link PacedText}). */
    public void status(String text) {
        show(paced.offer(text, field.clock().nowMicros()));
    }

    private void show(String text) {
        if (text != null) {
            status.setText(text);
        }
    }

    /**
     * Re-reads the option lists when they changed; cheap otherwise. Every datagram moves the robot
     * registry's version, so a change there alone is read at most twice a second (the sources
     * come with the option lists, whose version is read at once).
     */
    public void refresh() {
        long ov = field.options().version();
        long rv = field.robots().version();
        long now = field.clock().nowMicros();
        show(paced.due(now));
        if (ov == seenOptionsVersion && (rv == seenRobotsVersion || now - readMicros < REREAD_MICROS)) {
            return;
        }
        readMicros = now;
        seenOptionsVersion = ov;
        seenRobotsVersion = rv;
        List<ViewSource> found = new ArrayList<>();
        for (RobotSnapshot r : field.robots().robots()) {
            RobotOptions ro = field.options().options(r.id(), r.origin());
            for (OptionState o : ro.options()) {
                if (kinds.contains(o.kind()) && !found.contains(new ViewSource(r.id(), o.name()))) {
                    found.add(new ViewSource(r.id(), o.name()));
                }
            }
        }
        for (var k : field.stores().latest().translatedSources(rosKinds)) {
            if (!found.contains(new ViewSource(k.robotId(), k.option()))) {
                found.add(new ViewSource(k.robotId(), k.option()));
            }
        }
        ViewSource current = choice.getValue();
        if (current != null && current.isSet() && !found.contains(current)) {
            found.add(0, current);
        }
        if (!found.equals(choice.getItems())) {
            choice.setItems(FXCollections.observableArrayList(found));
            if (current != null) {
                choice.getSelectionModel().select(current);
            } else if (!found.isEmpty()) {
                choice.getSelectionModel().select(0);
            }
        }
    }
}
