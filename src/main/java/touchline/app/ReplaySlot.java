package touchline.app;

/**
 * The replay open now, if any: shared by the live field (whose clocks follow a replay) and the
 * replays service (which opens and closes it). Package-private plumbing of the composition root.
 */
final class ReplaySlot {

    private volatile Replay replay;

    Replay get() {
        return replay;
    }

    void set(Replay replay) {
        this.replay = replay;
    }

    boolean open() {
        return replay != null;
    }
}
