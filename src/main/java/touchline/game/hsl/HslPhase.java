package touchline.game.hsl;

/** The periods of an HSL game, with their wire gamePhase (3, TIMEOUT, is a state here). */
public enum HslPhase {
    NORMAL(0), PENALTY_SHOOT_OUT(1), EXTRA_TIME(2);

    private final int wire;

    HslPhase(int wire) {
        this.wire = wire;
    }

    public int wire() {
        return wire;
    }
}
