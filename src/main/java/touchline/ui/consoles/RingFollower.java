package touchline.ui.consoles;

import javafx.collections.ObservableList;
import touchline.model.store.SequencedRing;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * Follows a sequenced ring (the text log, the network log) into a list control's items, once
 * per frame: appends what arrived since the last frame, read up to the store's version at the
 * start so nothing is read twice; keeps the newest {@code shown} items, trimming the oldest in
 * batches of a tenth of that (one removal every few hundred lines instead of one per frame; the
 * window's CPU showed no difference either way, docs/archive/benchmarks-sessions.md "Twelfth session"); and after
 * {@link #reload()} (a filter changed) starts again from what the ring still holds. The
 * text view uses it directly, the debug console and the network console through {@link LogList}.
 *
 * @param <E> what the ring holds
 * @param <T> what the list shows
 */
final class RingFollower<E, T> {

    /** Reads a ring's entries after a sequence number, at most {@code max} (the newest). */
    interface Reader<E> {
        List<SequencedRing.Entry<E>> since(long afterSeq, int max);
    }

    private final ObservableList<T> items;
    private final int shown;
    private long seenSeq;
    private boolean reload = true;
    private int added;
    private int trimmed;

    RingFollower(ObservableList<T> items, int shown) {
        this.items = items;
        this.shown = shown;
    }

    /** Starts again: the next {@link #follow} clears the items and reads the ring afresh. */
    void reload() {
        reload = true;
    }

    /**
     * Appends the entries after the last one read, each mapped to an item ({@code null}: not
     * shown). Returns the newest entry read (shown or not), or {@code null} when the ring has
     * nothing new; costs one version check when nothing changed.
     */
    SequencedRing.Entry<E> follow(long version, Reader<E> reader, Function<E, T> item) {
        added = 0;
        trimmed = 0;
        if (reload) {
            items.clear();
            seenSeq = 0;
            reload = false;
        }
        if (version == seenSeq) {
            return null;
        }
        List<SequencedRing.Entry<E>> fresh = reader.since(seenSeq, shown);
        fresh.removeIf(e -> e.seq() > version); // what arrives while we read is next frame's
        seenSeq = version;
        if (fresh.isEmpty()) {
            return null;
        }
        List<T> add = new ArrayList<>(fresh.size());
        for (SequencedRing.Entry<E> e : fresh) {
            T t = item.apply(e.value());
            if (t != null) {
                add.add(t);
            }
        }
        items.addAll(add);
        added = add.size();
        int over = items.size() - shown;
        if (over > shown / 10) {
            items.remove(0, over);
            trimmed = over;
        }
        return fresh.get(fresh.size() - 1);
    }

    /** Items the last {@link #follow} removed from the front (the oldest, over the cap: at most a tenth more than shown is kept). */
    int trimmed() {
        return trimmed;
    }

    /** Items the last {@link #follow} appended. */
    int added() {
        return added;
    }
}
