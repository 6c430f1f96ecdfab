package touchline.ui.frame;

import javafx.scene.Node;
import javafx.scene.layout.BorderPane;
import touchline.app.LiveField;
import touchline.model.store.Latest;
import touchline.model.store.ViewStores;

import java.util.Optional;
import java.util.Set;

/**
 * A visualisation of one robot's option: a {@link SourceBar} on top, the drawing below.
 * Draws only when the option's newest value changed (or the view was resized), and reports
 * the value's receive time as shown.
 */
public abstract class SourcedView implements View {

    /** The live field the source bar lists robots from; its stores are the ones the view draws (the replay's while one is open). */
    protected final LiveField field;
    protected final SourceBar bar;
    protected final BorderPane root = new BorderPane();
    private long drawnVersion = -1;
    private ViewSource drawnSource = ViewSource.NONE;
    protected boolean dirty;

    protected SourcedView(LiveField field, Set<Integer> kinds, ViewSource initial) {
        this(field, kinds, kinds, initial);
    }

    /** A view listing the robots' options of {@code kinds} and the ROS 2 robots' topics shown as data of {@code rosKinds}. */
    protected SourcedView(LiveField field, Set<Integer> kinds, Set<Integer> rosKinds, ViewSource initial) {
        this.field = field;
        this.bar = new SourceBar(field, kinds, rosKinds, initial);
        root.setTop(bar);
    }

    @Override
    public Node node() {
        return root;
    }

    /** The bounded stores the view pulls from. */
    protected ViewStores stores() {
        return field.stores();
    }

    @Override
    public ViewSource source() {
        return bar.selected();
    }

    protected void status(String text) {
        bar.status(text);
    }

    @Override
    public void refresh(FrameContext frame) {
        bar.refresh();
        ViewSource s = bar.selected();
        if (!s.isSet()) {
            status("no source chosen");
            return;
        }
        Optional<Latest> latest = stores().latest().get(s.robotId(), s.option());
        if (latest.isEmpty()) {
            if (!s.equals(drawnSource)) {
                drawnSource = s;
                empty();
            }
            status("waiting for data from robot " + s.robotId() + " · " + s.option()
                    + " (switch it on in Debug options)");
            return;
        }
        Latest l = latest.get();
        if (l.version() == drawnVersion && s.equals(drawnSource) && !dirty) {
            return;
        }
        boolean fresh = l.version() != drawnVersion;
        drawnVersion = l.version();
        drawnSource = s;
        dirty = false;
        status(draw(l));
        if (fresh) {
            frame.shown(l.timeMicros());
        }
    }

    /** Draws one value; returns the status line (what was shown, what could not be). */
    protected abstract String draw(Latest latest);

    /** Clears the drawing when the source changed and has no data yet. */
    protected void empty() { }
}
