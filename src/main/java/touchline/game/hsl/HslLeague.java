package touchline.game.hsl;

import touchline.game.League;
import touchline.game.LeagueAction;

/**
 * How the one {@link touchline.game.RefereeEngine} runs an HSL game: timers are durations the
 * state runs down; an action during the robots' delay after a PLAYING whistle is applied to the
 * held copy too when it is legal there, and ends the delay when it is not (a goal, say), as the
 * official GameController does; after an undo, time since then is run again on the restored state.
 */
final class HslLeague implements League<HslState> {

    @Override
    public HslState copy(HslState s) {
        return s.copy();
    }

    @Override
    public boolean runTime(HslState s, long nowMs) {
        return s.advance(nowMs);
    }

    @Override
    public void apply(HslState s, LeagueAction<? super HslState> action, long nowMs) {
        HslState held = s.delayed;
        boolean legalForRobots = held != null && action.isLegal(held);
        action.apply(s, nowMs);
        if (held != null && s.delayed == held) {
            if (legalForRobots) {
                action.apply(held, nowMs);
            } else {
                s.delayed = null;
            }
        }
    }

    @Override
    public void restored(HslState s, long nowMs) {
        s.advance(nowMs);
    }

    @Override
    public String describe(HslState s, long nowMs) {
        return s.describe();
    }
}
