package touchline.game.hsl;

/**
 * The game states of the HSL GameController. A timeout is a state of its own here; on the wire
 * it is INITIAL with the game phase TIMEOUT.
 */
public enum HslPlayState {
    INITIAL(0), READY(1), SET(2), PLAYING(3), FINISHED(4), TIMEOUT(0);

    private final int wire;

    HslPlayState(int wire) {
        this.wire = wire;
    }

    public int wire() {
        return wire;
    }

    /** Whether team messages count against the budget and the READY/PLAYING timers can run. */
    boolean onField() {
        return this == READY || this == SET || this == PLAYING;
    }
}
