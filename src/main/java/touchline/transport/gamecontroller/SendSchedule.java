package touchline.transport.gamecontroller;

/**
 * When the GameController sends, as a pure calculation on a time scale of the caller's choice
 * (nanoseconds in the sender, milliseconds in tests). Datagrams go out on a fixed grid of one
 * interval from the start. Two ways to react to a change of the game:
 * <ul>
 * <li>{@link #everyChange} (our HL / SPL / 2014 sender): an extra datagram at once after every
 *     change, the grid stays where it is;</li>
 * <li>{@link #burstOnStop} (the official HSL GameController, {@code control_message_sender.rs}):
 *     only when the state robots get switches to stopped, a datagram at once and four more
 *     200 ms apart; the grid then continues one interval after the last of them.</li>
 * </ul>
 * Not thread-safe: the sender serialises access.
 */
public final class SendSchedule {

    /** Datagrams in the burst after play gets stopped, the first one included. */
    public static final int BURST_DATAGRAMS = 5;

    private final long interval;
    private final long burstSpacing;
    private final boolean burst;
    private long next;
    private int burstLeft;
    private boolean stopped;

    private SendSchedule(long start, long interval, long burstSpacing, boolean burst) {
        this.next = start;
        this.interval = interval;
        this.burstSpacing = burstSpacing;
        this.burst = burst;
    }

    /** An extra datagram after every change (the first datagram at {@code start}). */
    public static SendSchedule everyChange(long start, long interval) {
        return new SendSchedule(start, interval, 0, false);
    }

    /** The HSL schedule: a burst of {@link #BURST_DATAGRAMS} {@code burstSpacing} apart when play gets stopped. */
    public static SendSchedule burstOnStop(long start, long interval, long burstSpacing) {
        return new SendSchedule(start, interval, burstSpacing, true);
    }

    /** When the next scheduled datagram is due. */
    public long next() {
        return next;
    }

    /**
     * The scheduled datagram due at {@code due} went out at {@code now}: move to the next slot
     * (after a stall, skip the missed slots of the grid instead of sending them in a rush; the
     * datagrams of a burst are never skipped). Ignored when a burst began while it was being
     * sent: that datagram does not count as the burst's first.
     */
    public void sent(long due, long now) {
        if (due != next) {
            return;
        }
        if (burstLeft > 0 && --burstLeft > 0) {
            next += burstSpacing; // a late burst datagram still goes out, at once
            return;
        }
        next += interval;
        while (now - next >= 0) {
            next += interval;
        }
    }

    /**
     * The game changed at {@code now}; {@code stoppedNow} is whether the state robots get is
     * stopped.
     *
     * @return whether an extra datagram is due at once, off the grid ({@link #everyChange} only;
     *         a burst moves {@link #next()} to {@code now} instead)
     */
    public boolean changed(long now, boolean stoppedNow) {
        boolean switched = stoppedNow && !stopped;
        stopped = stoppedNow;
        if (!burst) {
            return true;
        }
        if (switched) {
            next = now;
            burstLeft = BURST_DATAGRAMS;
        }
        return false;
    }
}
