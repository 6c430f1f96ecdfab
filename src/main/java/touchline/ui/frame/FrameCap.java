package touchline.ui.frame;

/**
 * How often the views may redraw while data streams: at most {@link #perSecond()} times a
 * second (input is followed at once, whatever the cap). The console's {@code --max-fps}; 30 by
 * default. A lower cap saves a laptop's battery, and what is shown is then up to 1/N s older:
 * the UI budget's packet-to-screen p99 of 50 ms holds only at 30 (docs/benchmarks.md). Pure.
 */
public record FrameCap(int perSecond) {

    public static final int DEFAULT = 30;
    public static final int MIN = 1;
    public static final int MAX = 60;

    public FrameCap {
        if (perSecond < MIN || perSecond > MAX) {
            throw new IllegalArgumentException("--max-fps must be between " + MIN + " and " + MAX + " frames a second, not "
                    + perSecond);
        }
    }

    public static FrameCap standard() {
        return new FrameCap(DEFAULT);
    }

    /**
     * Whether a frame at {@code nowNanos} waits for a later one, the last frame that pulled the
     * views having been at {@code lastWorkNanos}. With JavaFX's 60 pulses a second, a cap of 30
     * pulls in every other pulse, 10 in every sixth.
     */
    public boolean holdsBack(long nowNanos, long lastWorkNanos) {
        return nowNanos - lastWorkNanos < minNanos();
    }

    /** The shortest time between two data frames: 1/N s less 1 % (33 ms at 30), so a pulse a little early still counts. */
    public long minNanos() {
        return 990_000_000L / perSecond;
    }
}
