package touchline.game;

/** A clock that only moves when told to: for tests, replays and simulations. Thread-safe. */
public final class ManualClock implements GameClock {

    private volatile long millis;

    public ManualClock(long startMillis) {
        this.millis = startMillis;
    }

    @Override
    public long millis() {
        return millis;
    }

    public synchronized void set(long millis) {
        this.millis = millis;
    }

    public synchronized void advance(long deltaMillis) {
        this.millis += deltaMillis;
    }
}
