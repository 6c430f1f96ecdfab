package touchline.game;

/**
 * One thing a referee (or a robot's return packet, or a script) can do to a game of any league,
 * in the manner of GameController3's actions: {@link #isLegal} says whether the rules allow it
 * in the given state, {@link #apply} changes the state. The faces only build actions; the
 * {@link RefereeEngine} applies them.
 *
 * @param <S> the league's state ({@link GameState}, {@code hsl.HslState})
 */
public interface LeagueAction<S> {

    boolean isLegal(S s);

    /** Applies the action; only called when {@link #isLegal} is true. */
    void apply(S s, long nowMs);

    /** Short human-readable form for logs and the undo list, e.g. {@code goal 13}. */
    String describe();

    /** False for what the network does (HSL team messages): not on the undo list. */
    default boolean undoable() {
        return true;
    }
}
