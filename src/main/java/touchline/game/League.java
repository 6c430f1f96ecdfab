package touchline.game;

/**
 * What differs between leagues in how the one {@link RefereeEngine} runs a game: how time
 * changes a state, how an action lands (the HSL robots' delayed copy), what an undo restores and
 * how a refusal names the state. The rules themselves are the actions' and the state's.
 *
 * @param <S> the league's state
 */
public interface League<S> {

    /** A deep copy (undo, readers). */
    S copy(S s);

    /** The changes time brings up to {@code nowMs}, before an action is checked; true when the state changed. */
    boolean runTime(S s, long nowMs);

    /** The timer's event: {@link #runTime} and whatever bookkeeping follows it; true when the state changed. */
    default boolean tick(S s, long nowMs) {
        return runTime(s, nowMs);
    }

    /** Applies a legal action. */
    default void apply(S s, LeagueAction<? super S> action, long nowMs) {
        action.apply(s, nowMs);
    }

    /** After an undo put {@code s} back: what time has done since. */
    default void restored(S s, long nowMs) {
    }

    /** How a refused action names the state, e.g. {@code state READY 1st half, ...}. */
    String describe(S s, long nowMs);
}
