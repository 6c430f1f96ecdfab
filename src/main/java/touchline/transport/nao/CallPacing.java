package touchline.transport.nao;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Per-method pacing of a NAO link ({@link NaoLinkConfig#minIntervalMillis}): a call made
 * within its method's minimum interval after the last one sent waits for the interval's end,
 * and a newer call of the same method replaces the waiting one, which ends as
 * {@link CallOutcome.Superseded}. Coalescing rather than rejecting keeps the robot's last
 * target the user's last input ("stop walking" right after "walk" is never dropped). Pure:
 * time is passed in (nanoseconds on any monotonic clock); used by one thread at a time.
 */
final class CallPacing {

    private final NaoLinkConfig config;
    private final Map<String, Long> lastSentNanos = new HashMap<>();
    private final Map<String, QueuedCall> waiting = new HashMap<>();
    private final AtomicLong timeouts = new AtomicLong();

    CallPacing(NaoLinkConfig config) {
        this.config = config;
    }

    /**
     * True when {@code call} is too early and now waits for its method's interval to end
     * (replacing, and superseding, an earlier waiting call of that method); false when it may
     * go out now.
     */
    boolean holdIfEarly(QueuedCall call, long now) {
        long interval = config.minIntervalMillis(call.call());
        if (interval <= 0) {
            return false;
        }
        String name = call.call().qualifiedName();
        Long last = lastSentNanos.get(name);
        if (last == null || now - last >= TimeUnit.MILLISECONDS.toNanos(interval)) {
            return false;
        }
        QueuedCall older = waiting.put(name, call);
        if (older != null && older != call) {
            older.end(new CallOutcome.Superseded());
        }
        return true;
    }

    /** Notes that a call of this method went out at {@code now}. */
    void sent(NaoCall call, long now) {
        lastSentNanos.put(call.qualifiedName(), now);
    }

    /**
     * The waiting calls whose interval is over at {@code now}, taken off; a call that waited
     * past its own timeout ends here as timed out instead.
     */
    List<QueuedCall> due(long now) {
        if (waiting.isEmpty()) {
            return List.of(); // asked on every pass of the link thread
        }
        List<QueuedCall> ready = new ArrayList<>();
        for (Iterator<QueuedCall> it = waiting.values().iterator(); it.hasNext(); ) {
            QueuedCall c = it.next();
            if (now - dueNanos(c) >= 0) {
                it.remove();
                if (now - c.deadlineNanos() >= 0) {
                    timeouts.incrementAndGet();
                    c.end(new CallOutcome.TimedOut(c.timeoutMillis()));
                } else {
                    ready.add(c);
                }
            }
        }
        return ready;
    }

    /** When the next waiting call is due, or {@code bound} when none is earlier. */
    long nextDue(long bound) {
        long next = bound;
        for (QueuedCall c : waiting.values()) {
            long due = dueNanos(c);
            if (due - next < 0) {
                next = due;
            }
        }
        return next;
    }

    /** Ends every waiting call with {@code outcome}; returns how many. */
    int failAll(CallOutcome.Lost outcome) {
        int n = waiting.size();
        for (QueuedCall c : waiting.values()) {
            c.end(outcome);
        }
        waiting.clear();
        return n;
    }

    int waiting() {
        return waiting.size();
    }

    /** Calls that waited past their own timeout. */
    long timeouts() {
        return timeouts.get();
    }

    private long dueNanos(QueuedCall c) {
        Long last = lastSentNanos.get(c.call().qualifiedName());
        return last == null ? c.submittedNanos()
                : last + TimeUnit.MILLISECONDS.toNanos(config.minIntervalMillis(c.call()));
    }
}
