package touchline.game.hsl;

import touchline.game.GameClock;
import touchline.game.LeagueAction;
import touchline.game.Outcome;
import touchline.game.RefereeAction;
import touchline.game.RefereeEngine;
import touchline.game.RefereedGame;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.TeamColour;

import java.util.List;

/**
 * One refereed HSL game: the one {@link RefereeEngine} with the {@link HslLeague}'s way of running
 * time and actions (an action during the robots' delay after a PLAYING whistle is applied to the
 * held copy too when it is legal there, and ends the delay when it is not), over an {@link HslState}. In the console its one owner is {@code app.game.GameRuntime};
 * access is serialised all the same; listeners hear about every change.
 */
public final class HslGame implements RefereedGame {

    /** How many actions can be undone. */
    public static final int UNDO_DEPTH = RefereeEngine.UNDO_DEPTH;

    private final RefereeEngine<HslState> engine;

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
        String bad = colourConflict(leftColours, rightColours);
        if (leftTeam == rightTeam) {
            throw new IllegalArgumentException("the two teams need different numbers");
        }
        if (bad != null) {
            throw new IllegalArgumentException(bad);
        }
        this.engine = new RefereeEngine<>(new HslLeague(),
                new HslState(rules, leftTeam, leftColours, rightTeam, rightColours, clock.millis()), clock);
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

    @Override
    public void addListener(Runnable onChange) {
        engine.addListener(onChange);
    }

    @Override
    public long now() {
        return engine.now();
    }

    /**
     * Lets time pass, checks legality, applies the action (also to the robots' held copy), notifies;
     * an {@link HslAction} or one every league shares, else refused.
     */
    @Override
    public Outcome perform(LeagueAction<?> action) {
        LeagueAction<? super HslState> own = RefereeAction.of(action, HslAction.class);
        return own == null ? RefereeAction.refused(action) : engine.perform(own);
    }

    @Override
    public boolean advance() {
        return engine.advance();
    }

    /** Reverts the last action; time since then is run again on the restored state. */
    @Override
    public Outcome undo() {
        return engine.undo();
    }

    @Override
    public List<String> undoList() {
        return engine.undoList();
    }

    public boolean isLegal(LeagueAction<?> action) {
        LeagueAction<? super HslState> own = RefereeAction.of(action, HslAction.class);
        return own != null && engine.read((s, now) -> {
            s.advance(now);
            return own.isLegal(s);
        });
    }

    /** A copy of the current state, safe to read on any thread. */
    public HslState snapshot() {
        return engine.read((s, now) -> {
            s.advance(now);
            return s.copy();
        });
    }

    @Override
    public GameControlData controlData() {
        return engine.read((s, now) -> {
            s.advance(now);
            return s.robotData();
        });
    }

    @Override
    public GameControlData trueData() {
        return engine.read((s, now) -> {
            s.advance(now);
            return s.trueData();
        });
    }

    @Override
    public boolean hasTeam(int number) {
        return engine.read((s, now) -> s.team(number) != null);
    }

    @Override
    public String describe() {
        return engine.read((s, now) -> {
            s.advance(now);
            return s.describe();
        });
    }
}
