package touchline.transport.gamecontroller;

import java.net.InetSocketAddress;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;

/**
 * Malformed GameController datagrams (return packets, game states), counted per source address
 * with the last reason, so the operator can see who sends garbage. Such packets are never
 * applied. At most {@link #MAX_SOURCES} sources get a line of their own; packets from any
 * further source are counted together under {@link #OTHER_SOURCES}, so a flood from many
 * addresses costs a count, not a table and an output that grow with it. Thread-safe.
 */
public final class BadPackets {

    /** Sources tallied one by one; the rest share one tally. */
    public static final int MAX_SOURCES = 64;
    /** The key of the shared tally of the sources beyond {@link #MAX_SOURCES}. */
    public static final String OTHER_SOURCES = "other sources";

    /**
     * Tally for one source.
     *
     * @param count      packets rejected so far
     * @param lastReason why the last one was rejected
     */
    public record Tally(long count, String lastReason) {
    }

    private final Map<String, Tally> bySource = new HashMap<>();

    /** Counts one packet; true when its source got a tally of its own just now (the first from it). */
    public synchronized boolean count(InetSocketAddress from, String reason) {
        String key = from == null ? "unknown" : from.getAddress().getHostAddress() + ":" + from.getPort();
        boolean fresh = !bySource.containsKey(key);
        int own = bySource.size() - (bySource.containsKey(OTHER_SOURCES) ? 1 : 0);
        if (fresh && own >= MAX_SOURCES) {
            key = OTHER_SOURCES;
            fresh = false;
        }
        bySource.merge(key, new Tally(1, reason), (a, b) -> new Tally(a.count + 1, reason));
        return fresh;
    }

    public synchronized long total() {
        return bySource.values().stream().mapToLong(Tally::count).sum();
    }

    /** Tallies by "address:port", sorted; at most {@link #MAX_SOURCES} and {@link #OTHER_SOURCES}. */
    public synchronized Map<String, Tally> bySource() {
        return new TreeMap<>(bySource);
    }
}
