package touchline.transport;

/**
 * Monotonic time in nanoseconds (any origin, unaffected by changes of the wall clock): for
 * deadlines, timeouts and pacing. The real one is {@code app.SystemClock}; tests pass a clock
 * they advance by hand.
 */
@FunctionalInterface
public interface MonotonicClock {

    long nanoTime();
}
