package touchline.app.game;

import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What was last heard from each sender of game states (by "address:port"), for at most
 * {@link #capacity} senders: a new one beyond it makes the table forget the sender heard
 * longest ago, and counts it. A flood of made-up sources (one host can send from 64 000 ports)
 * so costs a fixed amount of memory and time. Not thread-safe: its owner synchronizes.
 *
 * @param <V> what is kept per source
 */
final class RecentSources<V> {

    /** Senders kept by each table of the console: a field has one GameController, a lab a few. */
    static final int CAPACITY = 64;

    private final int capacity;
    private final Map<String, V> bySource = new LinkedHashMap<>(); // heard longest ago first
    private long forgotten;

    RecentSources(int capacity) {
        this.capacity = capacity;
    }

    RecentSources() {
        this(CAPACITY);
    }

    /** {@code source} was heard now, saying {@code value}. */
    void put(String source, V value) {
        bySource.remove(source); // to the end: heard most recently
        bySource.put(source, value);
        if (bySource.size() > capacity) {
            var eldest = bySource.keySet().iterator();
            eldest.next();
            eldest.remove();
            forgotten++;
        }
    }

    V get(String source) {
        return bySource.get(source);
    }

    /** Sources kept, heard longest ago first. */
    Collection<Map.Entry<String, V>> entries() {
        return bySource.entrySet();
    }

    List<V> values() {
        return List.copyOf(bySource.values());
    }

    int size() {
        return bySource.size();
    }

    int capacity() {
        return capacity;
    }

    /** Sources forgotten to make room since the start. */
    long forgotten() {
        return forgotten;
    }
}
