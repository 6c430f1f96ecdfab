package touchline.ui.field;

import javafx.collections.FXCollections;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.Region;
import touchline.model.FramedField;

import java.util.ArrayList;
import java.util.List;

/**
 * The field view's "Frame" chooser (Alt+F, or Tab to it): automatic, or one of the frames the
 * ROS 2 robots told (their TF trees, their poses' and markers' {@code frame_id}); a frame chosen
 * from a saved layout stays listed while no robot names it yet.
 */
final class FrameChooser {

    /** The automatic entry (no ROS frame has parentheses in its name). */
    static final String AUTOMATIC = "(automatic)";

    private final FramedField model;
    private final Runnable changed;
    final Label label = new Label("_Frame");
    final ComboBox<String> choice = new ComboBox<>(FXCollections.observableArrayList(AUTOMATIC));

    FrameChooser(FramedField model, Runnable changed) {
        this.model = model;
        this.changed = changed;
        choice.setId("field-frame");
        choice.setValue(AUTOMATIC);
        choice.setTooltip(new Tooltip("The frame the ROS 2 robots' poses and markers are drawn in, through each robot's "
                + "TF tree; automatic: map, else the one frame the poses are in"));
        label.setMnemonicParsing(true);
        label.setLabelFor(choice);
        label.setMinWidth(Region.USE_PREF_SIZE);
        choice.setMinWidth(Region.USE_PREF_SIZE); // "(automatic)" whole: the status line gives way
        choice.valueProperty().addListener((o, was, now) -> {
            if (now != null) {
                model.choose(now.equals(AUTOMATIC) ? FramedField.AUTO : now);
                changed.run();
            }
        });
    }

    /** Shows {@code frame} chosen ({@link FramedField#AUTO}: automatic). */
    void select(String frame) {
        String entry = frame.isEmpty() ? AUTOMATIC : frame;
        if (!choice.getItems().contains(entry)) {
            choice.getItems().add(entry);
        }
        choice.setValue(entry);
    }

    /** Lists the frames seen now (cheap when they did not change). */
    void refresh() {
        List<String> entries = new ArrayList<>(model.frames().size() + 2);
        entries.add(AUTOMATIC);
        entries.addAll(model.frames());
        String current = choice.getValue();
        if (current != null && !entries.contains(current)) {
            entries.add(current);
        }
        if (!entries.equals(choice.getItems())) {
            choice.getItems().setAll(entries);
            choice.setValue(current);
        }
    }
}
