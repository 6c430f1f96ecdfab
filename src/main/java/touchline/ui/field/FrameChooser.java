package touchline.ui.field;

import javafx.collections.FXCollections;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.Region;
import touchline.model.FramedField;
import touchline.ui.frame.SourceBar;
import touchline.ui.frame.ViewSource;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * A view's "Frame" chooser (Alt+F, or Tab to it): automatic, or one of the frames the ROS 2
 * robots told (their TF trees, their poses' and markers' {@code frame_id}), as its view model lists
 * them; a frame chosen from a saved layout stays listed while no robot names it yet. The layout
 * keeps the choice with the view's source ({@link #layoutState}).
 */
final class FrameChooser {

    /** The automatic entry (no ROS frame has parentheses in its name). */
    static final String AUTOMATIC = "(automatic)";
    private static final String FRAME_PREFIX = "frame=";

    private final Supplier<? extends Collection<String>> frames;
    final Label label = new Label("_Frame");
    final ComboBox<String> choice = new ComboBox<>(FXCollections.observableArrayList(AUTOMATIC));

    /**
     * @param choose takes the chosen frame ({@link FramedField#AUTO} for automatic)
     * @param frames the frames to list now
     */
    FrameChooser(String id, String tooltip, Consumer<String> choose, Supplier<? extends Collection<String>> frames,
                 Runnable changed) {
        this.frames = frames;
        choice.setId(id);
        choice.setValue(AUTOMATIC);
        choice.setTooltip(new Tooltip(tooltip));
        label.setMnemonicParsing(true);
        label.setLabelFor(choice);
        label.setMinWidth(Region.USE_PREF_SIZE);
        choice.setMinWidth(Region.USE_PREF_SIZE); // "(automatic)" whole: the status line gives way
        choice.valueProperty().addListener((o, was, now) -> {
            if (now != null) {
                choose.accept(now.equals(AUTOMATIC) ? FramedField.AUTO : now);
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
        Collection<String> seen = frames.get();
        List<String> entries = new ArrayList<>(seen.size() + 2);
        entries.add(AUTOMATIC);
        entries.addAll(seen);
        String current = choice.getValue();
        if (current != null && !entries.contains(current)) {
            entries.add(current);
        }
        if (!entries.equals(choice.getItems())) {
            choice.getItems().setAll(entries);
            choice.setValue(current);
        }
    }

    /** The view's layout state: its source, and the frame when one was chosen ({@code frame=odom@1001//markers}); else null. */
    static String layoutState(String chosen, ViewSource source) {
        return chosen.isEmpty() || !chosen.matches("[^\\s@]+") ? null : FRAME_PREFIX + chosen + "@" + source.encode();
    }

    /** Chooses the frame and selects the source a {@link #layoutState} names; anything else changes nothing. */
    void restore(String state, SourceBar bar) {
        int at = state == null ? -1 : state.indexOf('@');
        if (state != null && state.startsWith(FRAME_PREFIX) && at > FRAME_PREFIX.length()) {
            select(state.substring(FRAME_PREFIX.length(), at));
            bar.select(ViewSource.decode(state.substring(at + 1)));
        }
    }
}
