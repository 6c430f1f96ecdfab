package touchline.serve;

import com.sun.management.HotSpotDiagnosticMXBean;

import java.lang.management.ManagementFactory;

/**
 * More heap before the garbage collector runs, for as long as the console serves viewers. The
 * window runs with a small soft heap limit ({@code -XX:SoftMaxHeapSize=256m} in the launcher) so
 * that it stays light on a laptop (issue 14); serving eight viewers allocates a frame per message
 * per viewer, and under that limit ZGC collected back to back (108 cycles in 30 s) and took the
 * window's frame rate with it (issue 16, docs/benchmarks.md). The limit is a manageable flag: it is
 * raised while serving and put back when serving stops (ZGC then returns the memory after its
 * uncommit delay). Never lowers it, never beyond the maximum heap; a JVM without the flag (or
 * without the management interface) is left as it is.
 */
final class HeapHeadroom implements AutoCloseable {

    /** The soft limit while serving (the launcher's maximum heap is 512 MB). */
    static final long WHILE_SERVING = 400L << 20;

    private static final String FLAG = "SoftMaxHeapSize";

    private final HotSpotDiagnosticMXBean vm;
    /** The value to put back, or null when nothing was changed. */
    private final String before;

    /** Raises the soft heap limit to {@code wanted} bytes (capped at the maximum heap) if it is lower. */
    HeapHeadroom(long wanted) {
        HotSpotDiagnosticMXBean found = null;
        String changed = null;
        try {
            found = ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class);
            long now = Long.parseLong(found.getVMOption(FLAG).getValue());
            long max = Long.parseLong(found.getVMOption("MaxHeapSize").getValue());
            long target = Math.min(wanted, max);
            if (now < target) {
                found.setVMOption(FLAG, Long.toString(target));
                changed = Long.toString(now);
            }
        } catch (RuntimeException e) {
            // no such flag or not manageable on this JVM: serving works, only with more collections
        }
        this.vm = found;
        this.before = changed;
    }

    /** Whether the limit was raised (and will be put back). */
    boolean raised() {
        return before != null;
    }

    @Override
    public void close() {
        if (before != null) {
            try {
                vm.setVMOption(FLAG, before);
            } catch (RuntimeException e) {
                // as above: nothing else depends on it
            }
        }
    }
}
