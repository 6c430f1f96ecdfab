package touchline.game;

/**
 * Where the game logic gets the time, in milliseconds on a monotonic scale. Live games use
 * {@link #system()}; tests and the golden replay pass a clock they set by hand.
 */
@FunctionalInterface
public interface GameClock {

    long millis();

    /** Monotonic wall time (System.nanoTime based, unaffected by clock changes). */
    static GameClock system() {
        return () -> System.nanoTime() / 1_000_000L;
    }
}
