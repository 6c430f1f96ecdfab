package touchline.model;

/**
 * Events and bytes per second over the last second, in ten 100 ms buckets. Not thread-safe
 * on its own: the owner synchronises.
 */
final class RateWindow {

    private static final long BUCKET_MICROS = 100_000;
    private static final int BUCKETS = 10;

    private final long[] counts = new long[BUCKETS];
    private final long[] bytes = new long[BUCKETS];
    private final long[] bucketStart = new long[BUCKETS];

    void add(long timeMicros, int size) {
        long slot = Math.floorDiv(timeMicros, BUCKET_MICROS);
        int i = (int) Math.floorMod(slot, BUCKETS);
        if (bucketStart[i] != slot) {
            bucketStart[i] = slot;
            counts[i] = 0;
            bytes[i] = 0;
        }
        counts[i]++;
        bytes[i] += size;
    }

    double perSecond(long nowMicros) {
        return sum(nowMicros, counts);
    }

    double bytesPerSecond(long nowMicros) {
        return sum(nowMicros, bytes);
    }

    private double sum(long nowMicros, long[] values) {
        long now = Math.floorDiv(nowMicros, BUCKET_MICROS);
        long total = 0;
        for (int i = 0; i < BUCKETS; i++) {
            if (bucketStart[i] > now - BUCKETS && bucketStart[i] <= now) {
                total += values[i];
            }
        }
        return total;
    }
}
