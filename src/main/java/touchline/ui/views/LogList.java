package touchline.ui.views;

import javafx.collections.FXCollections;
import javafx.collections.ObservableList;
import javafx.scene.control.IndexedCell;
import javafx.scene.control.ListView;
import javafx.scene.control.skin.VirtualFlow;

import java.util.List;

/**
 * A log in a list control that costs the same to follow whatever it holds. While it follows
 * (nothing selected, not paused) the list control holds only the newest {@link #TAIL} lines:
 * JavaFX 21's list measures every item again each time it scrolls, so following a
 * 5 000-line log took most of the window's FX thread (docs/benchmarks.md, "Thirteenth
 * session"). As soon as the user selects a line or pauses, it holds every line, with the
 * selection, the focus and the line at the top kept where they were; when the selection is
 * cleared (and not paused) it follows again.
 *
 * @param <T> what a line is
 */
final class LogList<T> {

    /** Lines held while following: more than any screen shows (about 45 on a 1080-px screen). */
    static final int TAIL = 200;

    private final ListView<T> list;
    private final ObservableList<T> all = FXCollections.observableArrayList();
    private final ObservableList<T> tail = FXCollections.observableArrayList();
    private boolean following = true;

    LogList(ListView<T> list) {
        this.list = list;
        list.setItems(tail);
    }

    /** Every line (what a {@link RingFollower} appends to and trims). */
    ObservableList<T> all() {
        return all;
    }

    /** True while the list control holds only the newest lines. */
    boolean following() {
        return following;
    }

    /**
     * A frame's first step, before its lines are appended to {@link #all()}: {@code follow}
     * says whether the newest line should show (nothing selected, not paused); when it should
     * not, the list control switches to every line (while the tail is still the end of all).
     */
    void beforeAppend(boolean follow) {
        if (!follow && following) {
            holdEverything();
        }
    }

    /** A frame's last step: {@code added} lines were appended to {@link #all()}; shows the newest when following. */
    void afterAppend(boolean follow, int added) {
        if (!follow) {
            return;
        }
        boolean changed = true;
        if (!following) {
            following = true;
            tail.setAll(newest());
            list.setItems(tail);
        } else {
            changed = keepTail(added);
        }
        if (changed && !tail.isEmpty()) {
            list.scrollTo(tail.size() - 1);
        }
    }

    /** Empties the log (the user's Clear). */
    void clear() {
        all.clear();
        tail.clear();
    }

    private List<T> newest() {
        return all.subList(Math.max(0, all.size() - TAIL), all.size());
    }

    /** Appends what {@link #all()} gained; starts afresh when it changed otherwise (a reload, a clear). True if the tail changed. */
    private boolean keepTail(int added) {
        int n = all.size();
        int before = n - added; // lines all held before this frame's
        boolean continues = added >= 0 && added <= TAIL && before >= 0
                && (tail.isEmpty() ? before == 0 : before > 0 && all.get(before - 1) == tail.get(tail.size() - 1));
        if (!continues) {
            tail.setAll(newest());
            return true;
        }
        if (added == 0) {
            return false;
        }
        int over = tail.size() + added - TAIL;
        if (over > 0) {
            tail.remove(0, over);
        }
        tail.addAll(all.subList(before, n));
        return true;
    }

    /** Switches the list control to every line, keeping the selection, focus and top line. */
    private void holdEverything() {
        int offset = all.size() - tail.size();
        List<Integer> selected = List.copyOf(list.getSelectionModel().getSelectedIndices());
        int focused = list.getFocusModel().getFocusedIndex();
        int top = firstVisible();
        following = false;
        list.setItems(all);
        for (int i : selected) {
            list.getSelectionModel().select(i + offset);
        }
        if (focused >= 0) {
            list.getFocusModel().focus(focused + offset);
        }
        list.scrollTo(Math.max(0, top + offset));
    }

    private int firstVisible() {
        if (list.lookup(".virtual-flow") instanceof VirtualFlow<?> flow) {
            IndexedCell<?> first = flow.getFirstVisibleCell();
            if (first != null) {
                return first.getIndex();
            }
        }
        return Math.max(0, tail.size() - 1);
    }
}
