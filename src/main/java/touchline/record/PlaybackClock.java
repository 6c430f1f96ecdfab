package touchline.record;

/**
 * The wall clock a {@link Player} paces itself by; tests pass a clock they advance by hand,
 * so speed and pause are checked without sleeping; the real one is {@code app.SystemClock}.
 */
@FunctionalInterface
public interface PlaybackClock {
    long nanoTime();
}
