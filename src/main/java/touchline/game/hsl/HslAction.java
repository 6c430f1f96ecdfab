package touchline.game.hsl;

import touchline.game.LeagueAction;

/**
 * One thing the referee (or, for team messages, the network) does to an HSL game, in the
 * manner of the official GameController's actions: {@link #isLegal} says whether the rules
 * allow it now, {@link #apply} changes the state. Time is not an argument: timers are
 * durations that {@link HslState} runs down before an action is checked. The actions whose rule
 * every league shares ({@code game.Goal}, {@code game.StartPenaltyShootout}) are
 * {@link touchline.game.RefereeAction}s instead.
 */
public interface HslAction extends LeagueAction<HslState> {

    /** Applies the action; only called when {@link #isLegal} is true. */
    void apply(HslState s);

    /** The engine's call: HSL timers are durations the state runs down, so the time is not needed here. */
    @Override
    default void apply(HslState s, long nowMs) {
        apply(s);
    }
}
