package touchline.game;

/** A clock that only moves when told to: the game tests' clock (a test fixture, not the product's). Thread-safe. */
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
