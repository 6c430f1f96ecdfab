package touchline.model.store;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

/**
 * A bounded, thread-safe log that numbers every entry. Writers append on the network thread;
 * a view remembers the last sequence number it showed and asks only for what came after, so
 * a frame costs what changed, not the whole log. The oldest entries fall off when full.
 */
public final class SequencedRing<T> {

    /** One entry and its position in the stream (1, 2, 3, ...). */
    public record Entry<T>(long seq, T value) { }

    private final Object[] items;
    private long next = 1; // sequence number of the next append
    private long first = 1; // sequence number of the oldest entry not forgotten

    public SequencedRing(int capacity) {
        if (capacity <= 0) {
            throw new IllegalArgumentException("capacity must be positive: " + capacity);
        }
        this.items = new Object[capacity];
    }

    public synchronized long append(T value) {
        long seq = next++;
        items[(int) (seq % items.length)] = value;
        return seq;
    }

    /** The newest sequence number, 0 while empty; doubles as the version counter. */
    public synchronized long version() {
        return next - 1;
    }

    public int capacity() {
        return items.length;
    }

    public synchronized int size() {
        return (int) Math.min(next - first, items.length);
    }

    /** Entries after {@code afterSeq} that match, oldest first, at most {@code max} (the newest ones). */
    @SuppressWarnings("unchecked")
    public synchronized List<Entry<T>> since(long afterSeq, int max, Predicate<? super T> filter) {
        long oldest = Math.max(first, next - items.length);
        long from = Math.max(afterSeq + 1, oldest);
        List<Entry<T>> out = new ArrayList<>();
        for (long s = next - 1; s >= from && out.size() < max; s--) {
            T v = (T) items[(int) (s % items.length)];
            if (filter.test(v)) {
                out.add(new Entry<>(s, v));
            }
        }
        java.util.Collections.reverse(out);
        return out;
    }

    public List<Entry<T>> since(long afterSeq, int max) {
        return since(afterSeq, max, v -> true);
    }

    public synchronized void clear() {
        java.util.Arrays.fill(items, null);
        next = 1;
        first = 1;
    }

    /**
     * Drops every entry but keeps numbering on, so a reader that remembers the last sequence
     * number it saw simply gets what is appended from now on.
     */
    public synchronized void forget() {
        java.util.Arrays.fill(items, null);
        first = next;
    }
}
