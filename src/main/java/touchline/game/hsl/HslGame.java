package touchline.game.hsl;

import touchline.game.GameClock;
import touchline.game.LeagueGame;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.TeamColour;

import java.util.function.BiFunction;

/**
 * One refereed HSL game: a {@link LeagueGame} with the {@link HslLeague}'s way of running time and
 * actions (an action during the robots' delay after a PLAYING whistle is applied to the held copy
 * too when it is legal there, and ends the delay when it is not; an undo runs time since again on
 * the restored state), over an {@link HslState}, taking {@link HslAction}s and the actions every
 * league shares. Its readers see time run on first.
 */
public final class HslGame extends LeagueGame<HslState> {

    /**
     * @param rules       release and competition
     * @param leftTeam    team number defending the left goal in the first half; it kicks off first
     * @param leftColours its field player and goalkeeper colours
     * @param rightTeam   the other team
     * @param rightColours its colours
     * @param clock       the time source
     */
    public HslGame(HslRules rules, int leftTeam, TeamColour[] leftColours, int rightTeam, TeamColour[] rightColours,
                   GameClock clock) {
        super(new HslLeague(), new HslState(rules, leftTeam, leftColours, rightTeam, rightColours, clock.millis()),
                clock, HslAction.class);
    }

    /**
     * Why these colours cannot play each other (the official launcher's rule: the field player
     * colours differ, and neither is the other team's goalkeeper colour), or null when they can.
     */
    public static String colourConflict(TeamColour[] a, TeamColour[] b) {
        if (a[0] == b[0]) {
            return "both teams' field players wear " + a[0];
        }
        if (a[0] == b[1] || b[0] == a[1]) {
            return "a team's field players wear the other goalkeeper's colour";
        }
        return null;
    }

    /** Runs time on to now first: the HSL timers are durations the state runs down. */
    @Override
    protected <R> R read(BiFunction<HslState, Long, R> read) {
        return super.read((s, now) -> {
            s.advance(now);
            return read.apply(s, now);
        });
    }

    /** A copy of the current state, safe to read on any thread. */
    public HslState snapshot() {
        return read((s, now) -> s.copy());
    }

    @Override
    public GameControlData controlData() {
        return read((s, now) -> s.robotData());
    }

    @Override
    public GameControlData trueData() {
        return read((s, now) -> s.trueData());
    }

    @Override
    public String describe() {
        return read((s, now) -> s.describe());
    }
}
