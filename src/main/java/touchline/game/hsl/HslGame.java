package touchline.game.hsl;

import touchline.game.GameClock;
import touchline.game.Outcome;
import touchline.game.RefereedGame;
import touchline.game.UndoHistory;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.TeamColour;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * One refereed HSL game: the {@link HslState}, the clock it runs on and the undo history. An
 * action during the robots' delay after a PLAYING whistle is applied to the held copy too
 * when it is legal there, and ends the delay when it is not (a goal, say), as the official
 * GameController does. In the console its one owner is {@code app.game.GameRuntime};
 * access is serialised all the same; listeners hear about every change.
 */
public final class HslGame implements RefereedGame {

    /** How many actions can be undone. */
    public static final int UNDO_DEPTH = 50;

    private final GameClock clock;
    private final UndoHistory<HslState> history = new UndoHistory<>(UNDO_DEPTH);
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private HslState state;

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
        this.clock = clock;
        this.state = new HslState(rules, leftTeam, leftColours, rightTeam, rightColours, clock.millis());
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
        listeners.add(onChange);
    }

    @Override
    public long now() {
        return clock.millis();
    }

    /** Lets time pass, checks legality, applies the action (also to the robots' held copy), notifies. */
    public Outcome perform(HslAction action) {
        Outcome outcome;
        synchronized (this) {
            state.advance(clock.millis());
            if (!action.isLegal(state)) {
                return new Outcome(false, "illegal now: " + action.describe() + " (" + state.describe() + ")");
            }
            if (action.undoable()) {
                history.push(action.describe(), state.copy());
            }
            HslState held = state.delayed;
            boolean legalForRobots = held != null && action.isLegal(held);
            action.apply(state);
            if (held != null && state.delayed == held) {
                if (legalForRobots) {
                    action.apply(held);
                } else {
                    state.delayed = null;
                }
            }
            outcome = new Outcome(true, action.describe());
        }
        notifyListeners();
        return outcome;
    }

    @Override
    public boolean advance() {
        boolean changed;
        synchronized (this) {
            changed = state.advance(clock.millis());
        }
        if (changed) {
            notifyListeners();
        }
        return changed;
    }

    /** Reverts the last action; time since then is run again on the restored state. */
    @Override
    public Outcome undo() {
        UndoHistory.Done<HslState> done;
        synchronized (this) {
            done = history.pop();
            if (done == null) {
                return new Outcome(false, "nothing to undo");
            }
            state = done.before();
            state.advance(clock.millis());
        }
        notifyListeners();
        return new Outcome(true, "undid " + done.description());
    }

    @Override
    public synchronized List<String> undoList() {
        return history.descriptions();
    }

    public synchronized boolean isLegal(HslAction action) {
        state.advance(clock.millis());
        return action.isLegal(state);
    }

    /** A copy of the current state, safe to read on any thread. */
    public synchronized HslState snapshot() {
        state.advance(clock.millis());
        return state.copy();
    }

    @Override
    public synchronized GameControlData controlData() {
        state.advance(clock.millis());
        return state.robotData();
    }

    @Override
    public synchronized GameControlData trueData() {
        state.advance(clock.millis());
        return state.trueData();
    }

    @Override
    public synchronized boolean hasTeam(int number) {
        return state.team(number) != null;
    }

    @Override
    public synchronized String describe() {
        state.advance(clock.millis());
        return state.describe();
    }

    private void notifyListeners() {
        for (Runnable r : listeners) {
            r.run();
        }
    }
}
