package touchline.ui.frame;

/**
 * Packet-to-screen latency histogram (0.1 ms buckets up to 2 s) filled on the FX thread and
 * read by the benchmark; it costs one array increment per shown item.
 */
public final class LatencyProbe {

    private static final int BUCKETS = 20_000; // 0.1 ms each
    private final long[] counts = new long[BUCKETS + 1];
    private long total;

    public synchronized void record(long micros) {
        int b = (int) Math.min(BUCKETS, Math.max(0, micros / 100));
        counts[b]++;
        total++;
    }

    public synchronized long count() {
        return total;
    }

    /** The latency below which {@code q} (0..1) of the samples fall, in milliseconds; NaN when empty. */
    public synchronized double quantileMillis(double q) {
        if (total == 0) {
            return Double.NaN;
        }
        long want = (long) Math.ceil(q * total);
        long seen = 0;
        for (int b = 0; b <= BUCKETS; b++) {
            seen += counts[b];
            if (seen >= want) {
                return (b + 1) / 10.0;
            }
        }
        return BUCKETS / 10.0;
    }

    public synchronized void reset() {
        java.util.Arrays.fill(counts, 0);
        total = 0;
    }
}
