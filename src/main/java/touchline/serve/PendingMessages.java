package touchline.serve;

import java.util.ArrayDeque;
import java.util.IdentityHashMap;
import java.util.Map;

/**
 * The messages waiting for one viewer's network, bounded. While the viewer keeps up every
 * message waits its turn; when its network is slow ({@code coalesce}) or the queue is full, a
 * new message replaces the one still waiting for the same subscription in place (newest wins,
 * the order between channels stays), so the queue never holds more than one message per
 * subscription plus the limit. Each message given up is counted as dropped.
 */
final class PendingMessages {

    /** A message waiting to go out; its content is replaced when a newer one of its subscription arrives. */
    static final class Pending {
        final Subscription subscription;
        long timeNanos;
        byte[] payload;

        Pending(Subscription subscription, long timeNanos, byte[] payload) {
            this.subscription = subscription;
            this.timeNanos = timeNanos;
            this.payload = payload;
        }
    }

    private final int limit;
    private final ArrayDeque<Pending> queue = new ArrayDeque<>();
    private final Map<Subscription, Pending> newest = new IdentityHashMap<>();
    private long dropped;

    PendingMessages(int limit) {
        if (limit < 1) {
            throw new IllegalArgumentException("a viewer's queue holds at least one message");
        }
        this.limit = limit;
    }

    /** Queues a message; {@code coalesce} when the viewer's network is not keeping up. */
    synchronized void offer(Subscription s, long timeNanos, byte[] payload, boolean coalesce) {
        Pending waiting = newest.get(s);
        if (waiting != null && (coalesce || queue.size() >= limit)) {
            waiting.timeNanos = timeNanos;
            waiting.payload = payload;
            dropped++;
            return;
        }
        if (queue.size() >= limit) {
            Pending oldest = queue.poll();
            forget(oldest);
            dropped++;
        }
        Pending p = new Pending(s, timeNanos, payload);
        queue.add(p);
        newest.put(s, p);
    }

    /** The next message to send, or null when none waits. */
    synchronized Pending poll() {
        Pending p = queue.poll();
        if (p != null) {
            forget(p);
        }
        return p;
    }

    private void forget(Pending p) {
        if (newest.get(p.subscription) == p) {
            newest.remove(p.subscription);
        }
    }

    synchronized int size() {
        return queue.size();
    }

    synchronized long dropped() {
        return dropped;
    }
}
