package touchline.bench;

/**
 * Messages decoded, counted by the receiving thread; in drain mode it also notes when the
 * expected count was reached and wakes the waiting benchmark thread.
 */
final class DecodedCounter {

    private final java.util.concurrent.atomic.AtomicLong count = new java.util.concurrent.atomic.AtomicLong();
    private volatile long expected = Long.MAX_VALUE;
    private volatile long reachedNanos;
    private volatile Thread waiter;

    void increment() {
        if (count.incrementAndGet() == expected) {
            reachedNanos = System.nanoTime();
            java.util.concurrent.locks.LockSupport.unpark(waiter);
        }
    }

    long sum() {
        return count.get();
    }

    /**
     * After a flood: the count once it has stopped changing for 200 ms, i.e. once the receiver
     * has emptied its socket buffer (nothing signals "empty", so the count is watched).
     */
    long awaitSettled() throws InterruptedException {
        long last = -1;
        while (count.get() != last) {
            last = count.get();
            Thread.sleep(200);
        }
        return last;
    }

    void expect(long total) {
        waiter = Thread.currentThread();
        reachedNanos = 0;
        expected = total;
    }

    /** When the expected count was reached, or the time given up at the deadline. */
    long await(long deadlineNanos) {
        long now;
        while (count.get() < expected && (now = System.nanoTime()) < deadlineNanos) {
            java.util.concurrent.locks.LockSupport.parkNanos(this, deadlineNanos - now);
        }
        long reached = reachedNanos;
        expected = Long.MAX_VALUE;
        return reached != 0 ? reached : System.nanoTime();
    }
}
