package touchline.ui.consoles;

import javafx.collections.FXCollections;
import javafx.collections.ObservableList;
import javafx.scene.control.Control;
import javafx.scene.control.FocusModel;
import javafx.scene.control.IndexedCell;
import javafx.scene.control.ListView;
import javafx.scene.control.MultipleSelectionModel;
import javafx.scene.control.TableView;
import javafx.scene.control.skin.VirtualFlow;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;

import touchline.model.store.SequencedRing;

import java.util.List;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.IntConsumer;
import java.util.function.Supplier;
import touchline.ui.render.SkinPart;

/**
 * A log in a list or table control that costs the same to follow whatever it holds. While it
 * follows (nothing selected, not paused) the control holds only the newest {@link #TAIL} lines
 * (up to {@link #TRIM_SLACK} more before the oldest go, in one cut):
 * JavaFX 21's list and table measure every item again each time they scroll, so following a
 * 5 000-line log took most of the window's FX thread (docs/archive/benchmarks-sessions.md, "Thirteenth
 * session"). As soon as the user selects a line or pauses, it holds every line, with the
 * selection, the focus and the line at the top kept where they were; when the selection is
 * cleared (and not paused) it follows again; while it holds every line, the lines on screen stay
 * where they are as the oldest go. It reads its ring through a {@link RingFollower}. The debug
 * console and the network console.
 *
 * @param <E> what the ring holds
 * @param <T> what a line is
 */
final class LogList<E, T> {

    /** Lines held while following: more than any screen shows (about 45 on a 1080-px screen). */
    static final int TAIL = 200;
    /**
     * ... and up to this many more before the oldest go, all in one frame: cutting the front of
     * the list moves every line to another row, so each row on screen gets a new text, is styled
     * and laid out again (most of the debug console's cost when it cut one line a frame;
     * docs/archive/benchmarks-sessions.md, "Sixteenth session"). Appending alone leaves the rows on screen with
     * their lines, and only the new ones are drawn.
     */
    static final int TRIM_SLACK = 200;

    private final Control control;
    private final SkinPart<VirtualFlow> flow;
    private final Consumer<ObservableList<T>> setItems;
    private final IntConsumer scrollTo;
    private final Supplier<MultipleSelectionModel<T>> selection;
    private final Supplier<FocusModel<T>> focus;
    private final ObservableList<T> all = FXCollections.observableArrayList();
    private final ObservableList<T> tail = FXCollections.observableArrayList();
    private final RingFollower<E, T> follower;
    private boolean following = true;
    /** Where the newest lines go instead of the control while it follows, or null: the control. */
    private Glance<T> glance;
    /** The last line the glance was given. */
    private T glanced;

    /**
     * What shows the newest lines while nobody uses the control ({@link #glance}): cheaper to follow
     * a log with than the control, which is what the user selects, scrolls and searches in.
     */
    interface Glance<T> {
        /** Shows these lines, the newest last, instead of what it showed. */
        void restart(List<T> newest);

        /** Shows these lines, the newest last, below what it showed. */
        void append(List<T> added);
    }

    /** @param shown lines held at most ({@link RingFollower}) */
    LogList(ListView<T> list, int shown) {
        this(list, list::setItems, list::scrollTo, list::getSelectionModel, list::getFocusModel, shown);
    }

    /** @param shown rows held at most ({@link RingFollower}) */
    LogList(TableView<T> table, int shown) {
        this(table, table::setItems, table::scrollTo, table::getSelectionModel, () -> table.getFocusModel(), shown);
    }

    private LogList(Control control, Consumer<ObservableList<T>> setItems, IntConsumer scrollTo,
                    Supplier<MultipleSelectionModel<T>> selection, Supplier<FocusModel<T>> focus, int shown) {
        this.follower = new RingFollower<>(all, shown);
        this.control = control;
        this.flow = new SkinPart<>(control, ".virtual-flow", VirtualFlow.class);
        this.setItems = setItems;
        this.scrollTo = scrollTo;
        this.selection = selection;
        this.focus = focus;
        setItems.accept(tail);
        control.addEventFilter(KeyEvent.KEY_PRESSED, this::arrowIntoTheLog);
    }

    /**
     * The selected line after the oldest went: a table's selection model does not move its
     * index with a cut at the front, so the selection slid onto another line at every cut (the
     * network console's datagram changed under the user every second or two). A selected line
     * that went with the oldest clears the selection: the log follows again.
     */
    private void keepSelected(int index) {
        if (index < 0) {
            selection.get().clearSelection();
            return;
        }
        if (selection.get().getSelectedIndex() != index) {
            selection.get().clearAndSelect(index);
        }
        focus.get().focus(index);
    }

    /**
     * Up or Down in a list that follows with nothing selected starts at the newest line, the one in
     * view: the control's own keys would move from its focus, a line out of view or none, and select the
     * oldest held. From then on the selection holds the log still and the keys move as usual.
     */
    private void arrowIntoTheLog(KeyEvent e) {
        boolean arrow = e.getCode() == KeyCode.UP || e.getCode() == KeyCode.DOWN;
        if (!arrow || e.isShiftDown() || e.isShortcutDown() || !following || tail.isEmpty()
                || !selection.get().isEmpty()) {
            return;
        }
        int newest = tail.size() - 1;
        selection.get().clearAndSelect(newest);
        focus.get().focus(newest);
        e.consume();
    }

    /**
     * While it follows, sends the newest lines to {@code to} instead of the control, which stands
     * still; {@code null} brings the control up to date at once and sends them there again. The
     * caller hides one of the two: the glance while the user is at the control (points at it, has
     * focused it, selected a line, paused, searches), the control otherwise.
     */
    void glance(Glance<T> to) {
        if (to == glance) {
            return;
        }
        glance = to;
        if (to != null) {
            glanced = null;
            sendToGlance(-1);
        } else if (following) {
            tail.setAll(newest());
            if (!tail.isEmpty()) {
                showNewest();
            }
        }
    }

    /** Every line held (up to {@code shown}, a tenth more before the oldest go). */
    ObservableList<T> all() {
        return all;
    }

    /** Starts again from what the ring still holds (a filter changed; resuming after a pause). */
    void reload() {
        follower.reload();
    }

    /** Holds every line without reading anything new (paused). */
    void holdEverything() {
        if (following) {
            showEverything();
        }
    }

    /**
     * One frame: reads what the ring gained ({@link RingFollower#follow}) and shows it.
     * {@code follow} says whether the newest line should show (nothing selected, not paused);
     * when it should not, the control holds every line and the lines on screen stay as the
     * oldest go. Returns the newest entry read, or {@code null} when the ring has nothing new.
     */
    SequencedRing.Entry<E> follow(boolean follow, long version, RingFollower.Reader<E> reader, Function<E, T> item) {
        int top = -1;
        if (!follow && following) {
            showEverything(); // before this frame's lines: the tail is still the end of all
        } else if (!follow) {
            int[] shown = onScreen();
            top = shown == null ? -1 : shown[0];
        }
        int selected = follow ? -1 : selection.get().getSelectedIndex();
        SequencedRing.Entry<E> newest = follower.follow(version, reader, item);
        if (!follow) {
            if (follower.trimmed() > 0 && top >= 0) {
                scrollTo.accept(Math.max(0, top - follower.trimmed())); // the lines on screen stay where they were
            }
            if (follower.trimmed() > 0 && selected >= 0) {
                keepSelected(selected - follower.trimmed());
            }
            return newest;
        }
        if (glance != null) {
            if (!following) {
                following = true;
                setItems.accept(tail); // brought up to date when the glance ends
            }
            sendToGlance(follower.added());
            return newest;
        }
        boolean changed = true;
        if (!following) {
            following = true;
            tail.setAll(newest());
            setItems.accept(tail);
        } else {
            changed = keepTail(follower.added());
        }
        if (changed && !tail.isEmpty()) {
            showNewest();
        }
        return newest;
    }

    /**
     * Scrolls to the newest line so that the rows on screen keep their lines and only the new
     * ones are drawn. The control's own {@code scrollTo} first puts the line at the top and then
     * back at the bottom, giving every row on screen another line (styled and laid out again,
     * each frame), and scrolls by the length the list had before this frame's lines, so the
     * newest one showed only a frame later. Here the control learns its new length first (a
     * layout), then its flow goes to the end.
     */
    private void showNewest() {
        if (control.getScene() != null && flow.get() != null) {
            control.layout();
            flow.get().setPosition(1);
        } else {
            scrollTo.accept(tail.size() - 1); // not laid out yet: its first layout scrolls
        }
    }

    /** Empties the log (the user's Clear). */
    void clear() {
        all.clear();
        tail.clear();
        if (glance != null) {
            sendToGlance(-1);
        }
    }

    private List<T> newest() {
        return all.subList(Math.max(0, all.size() - TAIL), all.size());
    }

    /** Whether the last {@code added} lines of {@link #all()} follow on {@code last} (null: follow on nothing). */
    private boolean continues(int added, T last) {
        int before = all.size() - added; // lines all held before this frame's
        return added >= 0 && added <= TAIL && before >= 0
                && (last == null ? before == 0 : before > 0 && all.get(before - 1) == last);
    }

    /** Gives the glance what {@link #all()} gained, or everything afresh when it changed otherwise ({@code added} -1: afresh). */
    private void sendToGlance(int added) {
        if (!continues(added, glanced)) {
            glance.restart(newest());
        } else if (added > 0) {
            glance.append(all.subList(all.size() - added, all.size()));
        }
        glanced = all.isEmpty() ? null : all.get(all.size() - 1);
    }

    /** Appends what {@link #all()} gained; starts afresh when it changed otherwise (a reload, a clear). True if the tail changed. */
    private boolean keepTail(int added) {
        int n = all.size();
        int before = n - added; // lines all held before this frame's
        if (!continues(added, tail.isEmpty() ? null : tail.get(tail.size() - 1))) {
            tail.setAll(newest());
            return true;
        }
        if (added == 0) {
            return false;
        }
        int over = tail.size() + added - TAIL;
        if (over > TRIM_SLACK) {
            tail.remove(0, over);
        }
        tail.addAll(all.subList(before, n));
        return true;
    }

    /**
     * Switches the control to every line, keeping the selection, the focus and the line at the
     * top; if the focused line (where the keyboard or a click left it) is not among the lines on
     * screen — a scroll asked for in the same frame is not laid out yet — it is centred instead; and
     * the focused line shows whole (the newest one the first Down selects sat at the bottom edge,
     * which the line at the top, now whole, pushed under the edge or the sideways scroll bar).
     */
    private void showEverything() {
        if (control.getScene() != null) {
            control.layout(); // a scroll asked for in this frame (the list taking over from the glance) is where the screen is
        }
        int offset = all.size() - tail.size();
        List<Integer> selected = List.copyOf(selection.get().getSelectedIndices());
        int focused = focus.get().getFocusedIndex();
        // the focus a list gives its first line by itself is no place of the user's: only a selection or
        // the keyboard in the list make one (else a pause centred the list on that first line, 200 back)
        boolean chosen = !selected.isEmpty() || control.isFocused();
        int anchor = !chosen ? -1 : focused >= 0 ? focused : selected.isEmpty() ? -1 : selected.get(selected.size() - 1);
        int[] shown = onScreen();
        int top = shown == null ? Math.max(0, tail.size() - 1) : shown[0];
        if (anchor >= 0 && shown != null && (anchor < shown[0] || anchor > shown[1])) {
            top = Math.max(0, anchor - (shown[1] - shown[0]) / 2);
        }
        following = false;
        setItems.accept(all);
        for (int i : selected) {
            selection.get().select(i + offset);
        }
        if (focused >= 0) {
            focus.get().focus(focused + offset);
        }
        scrollTo.accept(Math.max(0, top + offset));
        if (anchor >= 0 && control.getScene() != null && flow.get() != null) {
            control.layout(); // every line and the line at the top in place, then the anchor whole:
            flow.get().scrollTo(anchor + offset); // the top line's row was cut, the bottom one may be now
        }
    }

    /** The first and last line on screen, or null before the control is laid out. */
    private int[] onScreen() {
        if (flow.get() != null) {
            IndexedCell<?> first = flow.get().getFirstVisibleCell();
            IndexedCell<?> last = flow.get().getLastVisibleCell();
            if (first != null && last != null) {
                return new int[] {first.getIndex(), last.getIndex()};
            }
        }
        return null;
    }
}
