package touchline.game;

/**
 * One thing a referee (or a robot's return packet, or a script) can do to a game of the
 * Humanoid League (or SPL) rules: a {@link LeagueAction} on a {@link GameState}. The UI and the
 * CLI only build actions and hand them to {@link Game#perform}; they never change a state themselves.
 * The actions whose rule every league shares ({@link Goal}, {@link StartPenaltyShootout}) are
 * {@link RefereeAction}s instead.
 */
public interface Action extends LeagueAction<GameState> {
}
