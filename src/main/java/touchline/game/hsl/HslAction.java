package touchline.game.hsl;

/**
 * One thing the referee (or, for team messages, the network) does to an HSL game, in the
 * manner of the official GameController's actions: {@link #isLegal} says whether the rules
 * allow it now, {@link #apply} changes the state. Time is not an argument: timers are
 * durations that {@link HslState} runs down before an action is checked.
 */
public interface HslAction {

    boolean isLegal(HslState s);

    /** Applies the action; only called when {@link #isLegal} is true. */
    void apply(HslState s);

    /** Short form for logs and the undo list, e.g. {@code goal 5}. */
    String describe();

    /** False for what the network does (team messages): not on the undo list. */
    default boolean undoable() {
        return true;
    }
}
