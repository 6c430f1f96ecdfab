package touchline.game;

/** INITIAL → READY (also ends a timeout): robots walk to their kick-off positions. */
public record ToReady() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        // A penalty shoot-out goes from INITIAL straight to SET.
        return s.state == PlayState.INITIAL
                && (s.secondary == SecondaryState.NORMAL || s.secondary == SecondaryState.TIMEOUT);
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.secondary = SecondaryState.NORMAL;
        s.enter(PlayState.READY, nowMs);
    }

    @Override
    public String describe() {
        return "ready";
    }
}
