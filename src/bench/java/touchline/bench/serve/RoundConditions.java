package touchline.bench.serve;

import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.util.Locale;

/**
 * What else happened during a measured round, to tell a slow round's cause: the collector's
 * pauses and cycles (by its MXBeans: ZGC reports "ZGC Pauses" and "ZGC Cycles"), the CPU
 * this process got against the machine's cores, and the machine's load average at the end.
 */
public final class RoundConditions {

    private final long startNanos = System.nanoTime();
    private final long startCpu = processCpuNanos();
    private final long[] startCount;
    private final long[] startMillis;

    public RoundConditions() {
        var beans = ManagementFactory.getGarbageCollectorMXBeans();
        startCount = beans.stream().mapToLong(GarbageCollectorMXBean::getCollectionCount).toArray();
        startMillis = beans.stream().mapToLong(GarbageCollectorMXBean::getCollectionTime).toArray();
    }

    private static long processCpuNanos() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() : -1;
    }

    /** e.g. "GC: ZGC Cycles 3 (412 ms), ZGC Pauses 9 (0.4 ms); process CPU 1.31 of 2 cores; load average 11.2". */
    public String since() {
        StringBuilder s = new StringBuilder("GC:");
        var beans = ManagementFactory.getGarbageCollectorMXBeans();
        for (int i = 0; i < beans.size() && i < startCount.length; i++) {
            s.append(i == 0 ? " " : ", ").append(beans.get(i).getName()).append(' ')
                    .append(beans.get(i).getCollectionCount() - startCount[i]).append(" (")
                    .append(beans.get(i).getCollectionTime() - startMillis[i]).append(" ms)");
        }
        double wall = System.nanoTime() - startNanos;
        int cores = Runtime.getRuntime().availableProcessors();
        s.append(String.format(Locale.ROOT, "; process CPU %.2f of %d cores; load average %.1f",
                (processCpuNanos() - startCpu) / wall, cores, ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage()));
        return s.toString();
    }
}
