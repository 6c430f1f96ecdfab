package touchline.bench.bridges;

/**
 * The share of one core a process used between two readings of its CPU time: the budgets say
 * "% of a core", so 100 is one core busy and two cores busy read 200.
 */
public final class CpuMeter {

    private final long startCpuNanos;
    private final long startWallNanos;

    public CpuMeter(long cpuNanos, long wallNanos) {
        this.startCpuNanos = cpuNanos;
        this.startWallNanos = wallNanos;
    }

    /** Percent of one core from the start reading to this one; NaN when no wall time passed or CPU time is unknown. */
    public double percentOfCore(long cpuNanos, long wallNanos) {
        long wall = wallNanos - startWallNanos;
        if (wall <= 0 || cpuNanos < 0 || startCpuNanos < 0) {
            return Double.NaN;
        }
        return 100.0 * (cpuNanos - startCpuNanos) / wall;
    }
}
