package touchline.game;

/**
 * The Humanoid League secondary state (STATE2_*), with its v12 wire code: game phases
 * (penalty shoot-out, overtime, timeout) and the set plays that interrupt PLAYING.
 */
public enum SecondaryState {
    NORMAL, PENALTYSHOOT, OVERTIME, TIMEOUT, DIRECT_FREEKICK, INDIRECT_FREEKICK, PENALTYKICK, CORNER_KICK,
    GOAL_KICK, THROW_IN;

    public int code() {
        return ordinal();
    }

    public boolean isSetPlay() {
        return ordinal() >= DIRECT_FREEKICK.ordinal();
    }
}
