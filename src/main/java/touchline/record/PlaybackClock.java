package touchline.record;

import touchline.transport.MonotonicClock;

/**
 * The monotonic clock a {@link Player} paces itself by; tests pass a clock they advance by hand,
 * so speed and pause are checked without sleeping; the real one is {@code app.SystemClock}.
 */
@FunctionalInterface
public interface PlaybackClock extends MonotonicClock {
}
