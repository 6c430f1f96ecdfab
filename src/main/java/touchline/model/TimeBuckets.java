package touchline.model;

/**
 * Events counted over a sliding window of fixed time buckets (e.g. the last minute in twelve
 * 5 s buckets): the budget guard's message rates and the debug rule's packet rates. Not
 * thread-safe on its own: the owner synchronises.
 */
final class TimeBuckets {

    private final long bucketMicros;
    private final long[] start;
    private final long[] count;

    TimeBuckets(long windowMicros, int buckets) {
        this.bucketMicros = windowMicros / buckets;
        this.start = new long[buckets];
        this.count = new long[buckets];
    }

    void add(long nowMicros) {
        long slot = Math.floorDiv(nowMicros, bucketMicros);
        int i = (int) Math.floorMod(slot, start.length);
        if (start[i] != slot) {
            start[i] = slot;
            count[i] = 0;
        }
        count[i]++;
    }

    /** Events in the whole window, the current (partial) bucket included. */
    long inWindow(long nowMicros) {
        return sum(nowMicros, true);
    }

    /** Events per second over the full buckets only (the current, partial one left out). */
    double perSecondOfFullBuckets(long nowMicros) {
        return sum(nowMicros, false) / ((start.length - 1) * bucketMicros / 1e6);
    }

    private long sum(long nowMicros, boolean withCurrent) {
        long slot = Math.floorDiv(nowMicros, bucketMicros);
        long total = 0;
        for (int i = 0; i < start.length; i++) {
            if (start[i] > slot - start.length && (withCurrent ? start[i] <= slot : start[i] < slot)) {
                total += count[i];
            }
        }
        return total;
    }
}
