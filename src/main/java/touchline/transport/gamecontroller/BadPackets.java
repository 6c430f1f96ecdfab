package touchline.transport.gamecontroller;

import java.net.InetSocketAddress;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Malformed GameController datagrams (return packets, game states), counted per source address
 * with the last reason, so the operator can see who sends garbage. Such packets are never
 * applied. Thread-safe.
 */
public final class BadPackets {

    /**
     * Tally for one source.
     *
     * @param count      packets rejected so far
     * @param lastReason why the last one was rejected
     */
    public record Tally(long count, String lastReason) {
    }

    private final Map<String, Tally> bySource = new ConcurrentHashMap<>();

    public void count(InetSocketAddress from, String reason) {
        String key = from == null ? "unknown" : from.getAddress().getHostAddress() + ":" + from.getPort();
        bySource.merge(key, new Tally(1, reason), (a, b) -> new Tally(a.count + 1, reason));
    }

    public long total() {
        return bySource.values().stream().mapToLong(Tally::count).sum();
    }

    /** Tallies by "address:port", sorted. */
    public Map<String, Tally> bySource() {
        return new TreeMap<>(bySource);
    }
}
