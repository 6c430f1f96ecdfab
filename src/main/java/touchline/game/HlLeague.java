package touchline.game;

/**
 * How the {@link RefereeEngine} runs a game of the Humanoid League (and SPL) rules: time ends
 * timed penalties and switches halves; the game clock is brought up to date after an action and
 * after the timer; an undo restores the state as it was.
 */
final class HlLeague implements League<GameState> {

    @Override
    public GameState copy(GameState s) {
        return s.copy();
    }

    @Override
    public boolean runTime(GameState s, long nowMs) {
        return s.advance(nowMs);
    }

    @Override
    public boolean tick(GameState s, long nowMs) {
        return s.tick(nowMs);
    }

    @Override
    public void apply(GameState s, LeagueAction<? super GameState> action, long nowMs) {
        action.apply(s, nowMs);
        s.syncClock(nowMs);
    }

    @Override
    public String describe(GameState s, long nowMs) {
        return "state " + s.describe(nowMs);
    }
}
