package touchline.transport.nao;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The call table of a NAO link: every request on the wire, by its request id, with the
 * deadline of its attempt. The robot's load-balancing broker answers out of order, so a reply
 * is matched by id; a reply whose id is no longer here (its call timed out, or it was never
 * ours) is counted as stray and dropped. Pure: no sockets, no threads, time is passed in
 * (nanoseconds on any monotonic clock). Used by one thread at a time (the link's lock); the
 * counters may be read from any thread.
 */
final class PendingCalls {

    /** A request on the wire: its call, when this attempt is over, and which attempt it is (1 = first). */
    record Sent(long id, QueuedCall call, long attemptDeadlineNanos, int attempt) {
    }

    private final Map<Long, Sent> byId = new LinkedHashMap<>();
    private long nextId = 1;
    private final AtomicLong strays = new AtomicLong();
    private final AtomicLong timeouts = new AtomicLong();

    /** The id for the next request; ids are never reused, so a late reply cannot match a newer call. */
    long nextId() {
        return nextId++;
    }

    /** Records a request that went out under {@code id}. */
    void sent(long id, QueuedCall call, long attemptDeadlineNanos, int attempt) {
        byId.put(id, new Sent(id, call, attemptDeadlineNanos, attempt));
    }

    /** The request a readable reply answers, taken off the table; null (counted as stray) when none waits. */
    Sent answered(long id) {
        Sent s = byId.remove(id);
        if (s == null) {
            strays.incrementAndGet();
        }
        return s;
    }

    /** The request an unreadable reply names, taken off the table, or null (not a stray: it was malformed). */
    Sent unreadable(long id) {
        return byId.remove(id);
    }

    /** The requests whose attempt is over at {@code now}, taken off the table, oldest id first. */
    List<Sent> expired(long now) {
        List<Sent> over = List.of(); // the link thread asks on every pass: no garbage while none expires
        for (Iterator<Sent> it = byId.values().iterator(); it.hasNext(); ) {
            Sent s = it.next();
            if (now - s.attemptDeadlineNanos() >= 0) {
                it.remove();
                if (over.isEmpty()) {
                    over = new ArrayList<>();
                }
                over.add(s);
            }
        }
        return over;
    }

    /** Ends a call whose last attempt expired: timed out after the time since it was made. */
    void timeOut(QueuedCall call, long now) {
        timeouts.incrementAndGet();
        call.end(new CallOutcome.TimedOut(TimeUnit.NANOSECONDS.toMillis(now - call.submittedNanos())));
    }

    /** Ends every request on the table with {@code outcome} (connection lost, link closed); returns how many. */
    int failAll(CallOutcome.Lost outcome) {
        int n = byId.size();
        for (Sent s : byId.values()) {
            s.call().end(outcome);
        }
        byId.clear();
        return n;
    }

    /** The earliest attempt deadline, or {@code bound} when none is earlier. */
    long nextDeadline(long bound) {
        long next = bound;
        for (Sent s : byId.values()) {
            if (s.attemptDeadlineNanos() - next < 0) {
                next = s.attemptDeadlineNanos();
            }
        }
        return next;
    }

    int size() {
        return byId.size();
    }

    /** Replies that matched no request on the table. */
    long strays() {
        return strays.get();
    }

    /** Calls ended as timed out here. */
    long timeouts() {
        return timeouts.get();
    }
}
