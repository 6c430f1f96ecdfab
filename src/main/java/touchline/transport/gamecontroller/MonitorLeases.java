package touchline.transport.gamecontroller;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The monitors registered with the embedded GameController, with two limits the official
 * GameControllers do not have: at most {@code capacity} hosts, and each only for a lease that
 * its next request renews, so a host that stopped asking is forgotten and a flood of requests
 * costs a refusal each, not a place in every send. A full table refuses newcomers (it never
 * evicts a live monitor for one). Times are the console clock's microseconds, given by the
 * caller. Thread-safe.
 */
final class MonitorLeases {

    /** What became of one request. */
    enum Request { REGISTERED, RENEWED, REFUSED_FULL }

    private final int capacity;
    private final long leaseMicros;
    private final Map<InetAddress, Long> lastRequest = new HashMap<>();

    MonitorLeases(int capacity, long leaseMicros) {
        if (capacity < 1 || leaseMicros <= 0) {
            throw new IllegalArgumentException("a monitor table needs a place and a lease: " + capacity + ", "
                    + leaseMicros + " µs");
        }
        this.capacity = capacity;
        this.leaseMicros = leaseMicros;
    }

    synchronized Request request(InetAddress host, long nowMicros) {
        if (lastRequest.containsKey(host)) {
            lastRequest.put(host, nowMicros);
            return Request.RENEWED;
        }
        if (lastRequest.size() >= capacity && expire(nowMicros).isEmpty()) {
            return Request.REFUSED_FULL;
        }
        lastRequest.put(host, nowMicros);
        return Request.REGISTERED;
    }

    /** Forgets every host whose lease ran out by {@code nowMicros}; returns them. */
    synchronized List<InetAddress> expire(long nowMicros) {
        List<InetAddress> gone = new ArrayList<>();
        lastRequest.entrySet().removeIf(e -> {
            boolean silent = nowMicros - e.getValue() >= leaseMicros;
            if (silent) {
                gone.add(e.getKey());
            }
            return silent;
        });
        return gone;
    }

    synchronized List<InetAddress> hosts() {
        return List.copyOf(lastRequest.keySet());
    }

    synchronized boolean isEmpty() {
        return lastRequest.isEmpty();
    }

    int capacity() {
        return capacity;
    }
}
