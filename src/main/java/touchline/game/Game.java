package touchline.game;

import touchline.protocol.gamecontroller.GameControlData;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * One refereed game: the {@link GameState}, the clock it is read against and the undo history.
 * In the console its one owner is {@code app.game.GameRuntime}, which calls every method on its
 * thread; access is serialised all the same. Listeners hear about every change (action, undo, or
 * a change that happened by itself in {@link #advance()}) on the thread that made it.
 */
public final class Game implements RefereedGame {

    /** How many actions can be undone. */
    public static final int UNDO_DEPTH = 50;

    private final GameClock clock;
    private final UndoHistory<GameState> history = new UndoHistory<>(UNDO_DEPTH);
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private GameState state;

    /**
     * @param params  league rules
     * @param teamA   team number on the left side in the first half (kicks off first)
     * @param colourA its colour (0 blue, 1 red, ...)
     * @param teamB   team number on the right side
     * @param colourB its colour
     * @param clock   the time source
     */
    public Game(LeagueParams params, int teamA, int colourA, int teamB, int colourB, GameClock clock) {
        if (teamA == teamB) {
            throw new IllegalArgumentException("the two teams need different numbers");
        }
        this.clock = clock;
        this.state = new GameState(params, teamA, colourA, teamB, colourB, clock.millis());
    }

    @Override
    public void addListener(Runnable onChange) {
        listeners.add(onChange);
    }

    @Override
    public long now() {
        return clock.millis();
    }

    /** Lets time-driven changes happen (then checks legality), applies the action, notifies. */
    public Outcome perform(Action action) {
        Outcome outcome;
        synchronized (this) {
            long now = clock.millis();
            state.advance(now);
            if (!action.isLegal(state)) {
                return new Outcome(false, "illegal now: " + action.describe() + " (state " + state.describe(now) + ")");
            }
            history.push(action.describe(), state.copy());
            action.apply(state, now);
            state.syncClock(now);
            outcome = new Outcome(true, action.describe());
        }
        notifyListeners();
        return outcome;
    }

    /** Applies changes that happen as time passes (penalties ending, half-time switch). */
    @Override
    public boolean advance() {
        boolean changed;
        synchronized (this) {
            long now = clock.millis();
            changed = state.advance(now);
            state.syncClock(now);
        }
        if (changed) {
            notifyListeners();
        }
        return changed;
    }

    /** Reverts the last applied action (timers keep running as if it had never happened). */
    @Override
    public Outcome undo() {
        UndoHistory.Done<GameState> done;
        synchronized (this) {
            done = history.pop();
            if (done == null) {
                return new Outcome(false, "nothing to undo");
            }
            state = done.before();
        }
        notifyListeners();
        return new Outcome(true, "undid " + done.description());
    }

    /** Descriptions of the undoable actions, most recent first. */
    @Override
    public synchronized List<String> undoList() {
        return history.descriptions();
    }

    public synchronized boolean isLegal(Action action) {
        return action.isLegal(state);
    }

    @Override
    public synchronized boolean hasTeam(int number) {
        return state.team(number) != null;
    }

    /** A copy of the current state, safe to read on any thread. */
    public synchronized GameState snapshot() {
        return state.copy();
    }

    /** The packet content right now (packetNumber 0). */
    @Override
    public synchronized GameControlData controlData() {
        return state.toControlData(clock.millis());
    }

    /** One line such as {@code PLAYING 1st half, 512 s, kick-off 7, 1:0}. */
    @Override
    public synchronized String describe() {
        return state.describe(clock.millis());
    }

    private void notifyListeners() {
        for (Runnable r : listeners) {
            r.run();
        }
    }
}
