package touchline.game;

/**
 * SET → PLAYING: the kick-off. Starts the half clock the first time in a half and, unless the
 * ball was dropped, the ball-free countdown for the defending team.
 */
public record ToPlaying() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.SET;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.enter(PlayState.PLAYING, nowMs);
        if (s.isPenaltyShootout()) {
            return; // the kick's own countdown runs, not the half clock
        }
        s.halfStarted = true;
        s.block(s.isDropBall() ? 0 : s.params.kickOffBlockSeconds(), nowMs);
    }

    @Override
    public String describe() {
        return "play";
    }
}
