package touchline.game;

/**
 * READY/SET/PLAYING → FINISHED: end of a half. After the first half the game switches to the
 * second half by itself at the next tick ({@link Game#advance}), so FINISHED is sent at least once.
 */
public record ToFinished() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.READY || s.state == PlayState.SET || s.state == PlayState.PLAYING;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        if (s.isPenaltyShootout()) {
            s.enter(PlayState.FINISHED, nowMs); // this kick is over (missed)
            return;
        }
        s.endSetPlay();
        s.block(0, nowMs);
        s.enter(PlayState.FINISHED, nowMs);
    }

    @Override
    public String describe() {
        return "finish";
    }
}
