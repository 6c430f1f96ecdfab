package touchline.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * CPU time the receiving threads of this process spend while they drain, by role: the
 * baseline's receiver, the UDP event loop, the stage that publishes to the model, the rest.
 * On a machine shared with other work a drain's wall-clock time mostly measures the wait for a
 * core; a thread's CPU time does not, so the ingest benchmark also reports CPU per datagram.
 * Counted only between {@link #begin} and {@link #end} (around each drain), so what threads do
 * while the receiver is held (the reliable streams' 10 ms timer) is left out. The measuring
 * thread itself is left out; the JVM's GC and compiler threads are not Java threads of ours
 * and not counted.
 */
final class ThreadCpu {

    static final String RECEIVER = "baseline receiver";
    static final String EVENT_LOOP = "event loop";
    static final String STAGE = "stage (touchline-decode)";
    static final String OTHER = "other";

    private final ThreadMXBean mx = ManagementFactory.getThreadMXBean();
    private final long[] ids;
    private final String[] roles;
    private final long[] atBegin;
    private final Map<String, Long> total = new TreeMap<>();

    /** The threads alive now (the receiver's are started before the drains begin). */
    ThreadCpu() {
        long self = Thread.currentThread().getId();
        List<Thread> threads = new ArrayList<>();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getId() != self) {
                threads.add(t);
            }
        }
        ids = new long[threads.size()];
        roles = new String[threads.size()];
        for (int i = 0; i < ids.length; i++) {
            ids[i] = threads.get(i).getId();
            roles[i] = role(threads.get(i).getName());
        }
        atBegin = new long[ids.length];
    }

    /** Before the receiver is let go. */
    void begin() {
        for (int i = 0; i < ids.length; i++) {
            atBegin[i] = mx.getThreadCpuTime(ids[i]);
        }
    }

    /** After it has drained: adds each thread's CPU time since {@link #begin} to its role. */
    void end() {
        for (int i = 0; i < ids.length; i++) {
            long now = mx.getThreadCpuTime(ids[i]);
            if (now >= 0 && atBegin[i] >= 0) {
                total.merge(roles[i], now - atBegin[i], Long::sum);
            }
        }
    }

    /** CPU nanoseconds per role over every drain so far. */
    Map<String, Long> total() {
        return new TreeMap<>(total);
    }

    static String role(String threadName) {
        if (threadName.startsWith("baseline-receiver")) {
            return RECEIVER;
        } else if (threadName.startsWith("multiThreadIoEventLoopGroup")) {
            return EVENT_LOOP;
        } else if (threadName.equals("touchline-decode")) {
            return STAGE;
        }
        return OTHER;
    }
}
