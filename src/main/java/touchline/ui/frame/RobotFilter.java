package touchline.ui.frame;

import javafx.collections.FXCollections;
import javafx.scene.control.ComboBox;
import touchline.model.RobotSnapshot;
import touchline.app.LiveField;

import java.util.ArrayList;
import java.util.List;

/** A "which robot" chooser ("all robots" or one ID) that follows the robots seen. */
public final class RobotFilter extends ComboBox<String> {

    static final String ALL = "all robots";
    private final LiveField field;
    private long seenVersion = -1;
    private boolean read;
    private long readMicros;

    public RobotFilter(LiveField field) {
        this.field = field;
        getItems().add(ALL);
        getSelectionModel().select(ALL);
    }

    /** The chosen robot ID, or -1 for all. */
    public int robotId() {
        String v = getValue();
        return v == null || v.equals(ALL) ? -1 : Integer.parseInt(v.substring("robot ".length()));
    }

    public void refresh() {
        long v = field.robots().version();
        long now = field.clock().nowMicros();
        // every datagram moves the version: the robot list is read at most twice a second (the first
        // time at once: a "never read" of Long.MIN_VALUE overflowed now - readMicros and kept the list empty)
        if (v == seenVersion || read && now - readMicros < touchline.ui.frame.SourceBar.REREAD_MICROS) {
            return;
        }
        read = true;
        readMicros = now;
        seenVersion = v;
        List<String> items = new ArrayList<>();
        items.add(ALL);
        for (RobotSnapshot r : field.robots().robots()) {
            if (!items.contains("robot " + r.id())) { // a replayed robot 3 beside the live one: one filter entry
                items.add("robot " + r.id());
            }
        }
        if (!items.equals(getItems())) {
            String keep = getValue();
            setItems(FXCollections.observableArrayList(items));
            getSelectionModel().select(items.contains(keep) ? keep : ALL);
        }
    }
}
