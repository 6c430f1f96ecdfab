package touchline.game;

/**
 * Where the game logic gets the time, in milliseconds on a monotonic scale. Live games get the
 * real one ({@code app.SystemClock}, monotonic) through their constructor; tests and the golden replay pass a clock they set by hand.
 */
@FunctionalInterface
public interface GameClock {

    long millis();
}
