package touchline.game;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BiFunction;

/**
 * The one game engine of every league: a state, the clock it is read against, the undo history
 * and the listeners. An action is checked against the state with time run on, put on the undo
 * list and applied, as GameController3 does; the league ({@link League}) says how time and an
 * action land. Access is serialised (in the console one thread owns it, {@code app.game.GameRuntime});
 * listeners hear about every change on the thread that made it.
 *
 * @param <S> the league's state
 */
public final class RefereeEngine<S> {

    /** How many actions can be undone. */
    public static final int UNDO_DEPTH = 50;

    private final League<S> league;
    private final GameClock clock;
    private final UndoHistory<S> history = new UndoHistory<>(UNDO_DEPTH);
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private S state;

    public RefereeEngine(League<S> league, S initial, GameClock clock) {
        this.league = league;
        this.state = initial;
        this.clock = clock;
    }

    public void addListener(Runnable onChange) {
        listeners.add(onChange);
    }

    public long now() {
        return clock.millis();
    }

    /** Lets time pass, checks legality, applies the action, notifies. */
    public Outcome perform(LeagueAction<? super S> action) {
        Outcome outcome;
        synchronized (this) {
            long now = clock.millis();
            league.runTime(state, now);
            if (!action.isLegal(state)) {
                return new Outcome(false, "illegal now: " + action.describe() + " (" + league.describe(state, now) + ")");
            }
            if (action.undoable()) {
                history.push(action.describe(), league.copy(state));
            }
            league.apply(state, action, now);
            outcome = new Outcome(true, action.describe());
        }
        notifyListeners();
        return outcome;
    }

    /** The timer: applies the changes time brings; true when the state (not only a clock) changed. */
    public boolean advance() {
        boolean changed;
        synchronized (this) {
            changed = league.tick(state, clock.millis());
        }
        if (changed) {
            notifyListeners();
        }
        return changed;
    }

    /** Reverts the last action. */
    public Outcome undo() {
        UndoHistory.Done<S> done;
        synchronized (this) {
            done = history.pop();
            if (done == null) {
                return new Outcome(false, "nothing to undo");
            }
            state = done.before();
            league.restored(state, clock.millis());
        }
        notifyListeners();
        return new Outcome(true, "undid " + done.description());
    }

    /** Descriptions of the undoable actions, most recent first. */
    public synchronized List<String> undoList() {
        return history.descriptions();
    }

    /** Reads the state at the clock's now (a league may run time on first: {@code read} gets the live state). */
    public synchronized <R> R read(BiFunction<S, Long, R> read) {
        return read.apply(state, clock.millis());
    }

    private void notifyListeners() {
        for (Runnable r : listeners) {
            r.run();
        }
    }
}
