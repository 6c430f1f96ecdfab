package touchline.game;

/**
 * One thing a referee (or a robot's return packet, or a script) can do to a game, in the manner
 * of GameController3's actions: {@link #isLegal} says whether the rules allow it in the given
 * state, {@link #apply} changes the state. The UI and the CLI only build actions and hand them
 * to {@link Game#perform}; they never change a state themselves.
 */
public interface Action {

    boolean isLegal(GameState s);

    /** Applies the action; only called when {@link #isLegal} is true. */
    void apply(GameState s, long nowMs);

    /** Short human-readable form for logs and the undo list, e.g. {@code goal 13}. */
    String describe();
}
