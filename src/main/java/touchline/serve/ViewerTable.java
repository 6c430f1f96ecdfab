package touchline.serve;

import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The viewers connected right now; a viewer leaves the table when its connection closes, and
 * what it was sent and dropped stays in the totals.
 */
final class ViewerTable {

    private final Set<Viewer> viewers = ConcurrentHashMap.newKeySet();
    private final AtomicLong departedSent = new AtomicLong();
    private final AtomicLong departedDropped = new AtomicLong();

    void add(Viewer v) {
        viewers.add(v);
    }

    void remove(Viewer v) {
        if (viewers.remove(v)) {
            departedSent.addAndGet(v.sent());
            departedDropped.addAndGet(v.dropped());
        }
    }

    List<Viewer> all() {
        return List.copyOf(viewers);
    }

    int size() {
        return viewers.size();
    }

    int subscriptions() {
        return viewers.stream().mapToInt(Viewer::subscriptionCount).sum();
    }

    /** Messages sent to every viewer since the start, those gone included. */
    long sent() {
        return departedSent.get() + viewers.stream().mapToLong(Viewer::sent).sum();
    }

    long dropped() {
        return departedDropped.get() + viewers.stream().mapToLong(Viewer::dropped).sum();
    }
}
