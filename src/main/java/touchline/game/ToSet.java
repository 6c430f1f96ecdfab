package touchline.game;

/** READY → SET: robots stand still for the kick-off. */
public record ToSet() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.READY;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.enter(PlayState.SET, nowMs);
    }

    @Override
    public String describe() {
        return "set";
    }
}
