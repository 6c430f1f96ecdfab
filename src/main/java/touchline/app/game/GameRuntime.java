package touchline.app.game;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.game.LeagueAction;
import touchline.game.Outcome;
import touchline.game.RefereedGame;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The one owner of a refereed game (GameController3's runtime task): its thread {@value #THREAD}
 * is the only one that changes the game. The referee's buttons and commands, robots' return
 * packets and the sender's timer only enqueue events ({@link #perform}, {@link #undo},
 * {@link #tick}, {@link #timed()}); the owner applies them one at a time in the order they came and, after each,
 * publishes an immutable {@link RefereeSnapshot} that the sender, the views and the CLI read.
 * The sender never waits for the owner: a periodic send runs the newest snapshot's time on to
 * its own instant ({@link #timed()}).
 * Listeners hear of every change on the owner thread and must only hand it on (the sender's
 * wake-up). Events enqueued before {@link #start()} wait for it; after {@link #close()} they are
 * refused at once.
 */
public final class GameRuntime implements AutoCloseable {

    /** The owner thread's name. */
    public static final String THREAD = "gc-game";
    /**
     * How long an event may wait for its outcome before a face says the owner did not answer
     * ({@link #outcome}, {@link #unanswered}).
     */
    public static final long ANSWER_MS = 2_000;
    private static final Logger LOG = LoggerFactory.getLogger(GameRuntime.class);

    private final RefereedGame game;
    private final Deque<Runnable> events = new ArrayDeque<>();
    private final List<Consumer<RefereeSnapshot>> listeners = new CopyOnWriteArrayList<>();
    private volatile RefereeSnapshot snapshot;
    /** Set by {@link #timed()}, cleared by the owner when it runs the timer event (before the queue's next). */
    private final AtomicBoolean timerDue = new AtomicBoolean();
    /** Set by the game's own listener; read and cleared by the owner after each event. */
    private volatile boolean changed;
    private volatile Thread owner;
    private volatile boolean closed;

    /** @param game the game this runtime owns from now on: nobody else calls its actions */
    public GameRuntime(RefereedGame game) {
        this.game = game;
        this.snapshot = RefereeSnapshot.of(game);
        game.addListener(() -> changed = true);
    }

    /** Starts the owner thread (once). */
    public synchronized void start() {
        if (owner != null || closed) {
            return;
        }
        owner = new Thread(this::run, THREAD);
        owner.setDaemon(true);
        owner.start();
    }

    /** The game's clock (a read, not a change). */
    public long now() {
        return game.now();
    }

    /** The game as of the last event. */
    public RefereeSnapshot snapshot() {
        return snapshot;
    }

    /** Called on the owner thread after every event that changed the game, with the new snapshot. */
    public void addListener(Consumer<RefereeSnapshot> onChange) {
        listeners.add(onChange);
    }

    /** Enqueues an action; the game refuses one of another league's rules (an HSL action in an HL game). */
    public CompletableFuture<Outcome> perform(LeagueAction<?> action) {
        return submit(() -> game.perform(action));
    }

    /** Enqueues an undo of the last action. */
    public CompletableFuture<Outcome> undo() {
        return submit(game::undo);
    }

    /**
     * The timer's event: lets the changes time brings happen (penalties end, halves switch);
     * completes with the snapshot after them.
     */
    public CompletableFuture<RefereeSnapshot> tick() {
        CompletableFuture<RefereeSnapshot> done = new CompletableFuture<>();
        if (!enqueue(() -> {
            try {
                game.advance();
                done.complete(publish());
            } catch (RuntimeException e) {
                done.completeExceptionally(e);
                throw e;
            }
        })) {
            done.complete(snapshot);
        }
        return done;
    }

    /**
     * The sender's timer (a periodic send): the newest snapshot with time run on to the game
     * clock's now ({@link RefereeSnapshot#at}), computed on the caller's thread. It never waits
     * for the owner, so a real-time sender keeps its grid however busy the owner is (listeners,
     * events queued ahead, a thread of lower priority); the owner's own timer event is asked
     * for too (a flag, one at a time, run before the queue's next), so the owner publishes what
     * time changed and its listeners hear of it. It takes no lock the owner holds.
     */
    public RefereeSnapshot timed() {
        if (!timerDue.getAndSet(true)) {
            LockSupport.unpark(owner); // no lock: the owner may hold the queue's while it is not scheduled
        }
        RefereeSnapshot s = snapshot; // before the clock: time is only ever run on
        return s.at(game.now());
    }

    /**
     * A command's wait for its own event's outcome (the CLI's; a view never waits, it takes the
     * outcome at a frame once the future is done): the owner works in memory only, so this is
     * the events ahead in the queue; a stopped or stuck owner is an outcome, not a hang.
     */
    public static Outcome outcome(CompletableFuture<Outcome> pending) {
        try {
            return pending.get(ANSWER_MS, TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            return unanswered();
        } catch (ExecutionException e) {
            return new Outcome(false, "failed: " + e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Outcome(false, "interrupted");
        }
    }

    /** What a face says of an event the owner has not answered within {@link #ANSWER_MS}. */
    public static Outcome unanswered() {
        return new Outcome(false, "the GameController did not answer within " + ANSWER_MS + " ms");
    }

    private CompletableFuture<Outcome> submit(Supplier<Outcome> event) {
        CompletableFuture<Outcome> done = new CompletableFuture<>();
        if (!enqueue(() -> {
            try {
                Outcome o = event.get();
                publish();
                done.complete(o);
            } catch (RuntimeException e) {
                done.completeExceptionally(e);
                throw e;
            }
        })) {
            done.complete(new Outcome(false, "the GameController is stopped"));
        }
        return done;
    }

    private boolean enqueue(Runnable event) {
        synchronized (this) {
            if (closed) {
                return false;
            }
            events.addLast(event);
        }
        LockSupport.unpark(owner);
        return true;
    }

    /**
     * The next event: the sender's timer when it is due (ahead of the queue: an action runs time
     * on before it applies anyway), else the queue's first; null once closed and empty, or interrupted.
     */
    private Runnable take() {
        while (true) {
            if (timerDue.getAndSet(false)) {
                return this::timer;
            }
            synchronized (this) {
                Runnable e = events.pollFirst();
                if (e != null || closed) {
                    return e;
                }
            }
            LockSupport.park(this);
            if (Thread.currentThread().isInterrupted()) {
                return null;
            }
        }
    }

    private void timer() {
        game.advance();
        publish();
    }

    private void run() {
        for (Runnable event = take(); event != null; event = take()) {
            try {
                event.run();
            } catch (RuntimeException e) {
                LOG.error("a GameController event failed; the game goes on", e);
            }
        }
    }

    /** After an event, on the owner thread: the new snapshot, and the listeners when the game changed. */
    private RefereeSnapshot publish() {
        RefereeSnapshot s = RefereeSnapshot.of(game);
        snapshot = s;
        if (changed) {
            changed = false;
            for (Consumer<RefereeSnapshot> l : listeners) {
                l.accept(s);
            }
        }
        return s;
    }

    /** Runs the events already enqueued, then stops the owner; later events are refused. */
    @Override
    public void close() {
        Thread t;
        synchronized (this) {
            closed = true;
            t = owner;
        }
        LockSupport.unpark(t);
        if (t != null && t != Thread.currentThread()) {
            try {
                t.join(ANSWER_MS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
