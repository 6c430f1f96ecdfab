package touchline.game;

/**
 * An action whose rule is the same in every league ({@link Goal}): it asks the league's state
 * through {@link RefereeState}, so one class serves HL, SPL and HSL. A league's own actions are
 * {@link Action} (HL, SPL) and {@code hsl.HslAction}; {@link #of} says which an action is to a league.
 */
public interface RefereeAction extends LeagueAction<RefereeState> {

    /**
     * The action as one of a league's, or null when it is not: an action every league shares, or
     * one of the league's own ({@code own}, e.g. {@code Action.class}).
     */
    static <S extends RefereeState> LeagueAction<? super S> of(LeagueAction<?> action,
                                                              Class<? extends LeagueAction<S>> own) {
        if (action instanceof RefereeAction shared) {
            return shared;
        }
        return own.isInstance(action) ? own.cast(action) : null;
    }

    /** What a game answers to an action of another league. */
    static Outcome refused(LeagueAction<?> action) {
        return new Outcome(false, action.describe() + " is not an action of this game's rules");
    }
}
