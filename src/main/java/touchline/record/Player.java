package touchline.record;

import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Feeds a {@link Recording} into an {@link EnvelopeSink} (normally the application's
 * {@code EnvelopeBus}) paced by a clock: play, pause, speed 0.1x to 50x, seek by time or to
 * an event, loop a range, or everything as fast as possible ({@link #runToEnd()}). Controls
 * are thread-safe and may be called from the UI thread; envelopes are delivered on the
 * player's own thread ({@link #start()}) or on whichever thread calls {@link #pump()}, one
 * delivering thread at a time. A batch is taken under the player's lock and delivered outside
 * it, so a control never waits for a subscriber: a jump while a batch is delivered ends that
 * batch after the envelope in hand, and its {@code jumped} callback then runs on the delivering
 * thread, after that envelope and before anything from the new position.
 * The position advances with the clock: recording time = anchor + wall time elapsed x speed.
 * Every envelope it delivers is marked {@linkplain Envelope#asReplayed() replayed}, so nothing
 * that acts on the live field reacts to it. Whenever the position jumps (a seek, a loop going
 * round, playing again from the start) the {@code jumped} callback runs before the next
 * envelope is delivered, so what was built from the replay can start again from there; after a
 * seek, playing or paused, the state at the play head ({@link PlayHead}: the newest envelope of
 * each kind at or before it) is delivered first, so the views show that moment at once.
 * Over 400 lines because the controls, the paced pump and the unpaced run share one position,
 * one cursor and one lock, and the order of a jump against a batch in flight is kept by that lock.
 */
public final class Player implements AutoCloseable {

    public static final double MIN_SPEED = 0.1;
    public static final double MAX_SPEED = 50;
    /** Envelopes delivered per pump at most, so controls never wait long for the lock. */
    private static final int BATCH = 20_000;
    private static final long MAX_WAIT_NANOS = 20_000_000L;
    /** A loop over a range with no envelopes must not spin forever inside one pump. */
    private static final int MAX_LAPS_PER_PUMP = 1000;

    private final ReplaySession session;
    private final EnvelopeSink sink;
    private final PlaybackClock clock;
    private final Runnable jumped;
    /** What a batch delivers: an envelope from its file, or the {@link #JUMP} of a loop going round. */
    private record Due(Envelope envelope, String source) { }

    private static final Due JUMP = new Due(null, "");

    private ReplaySession.Cursor cursor;
    private Envelope pending;
    private String pendingSource = "";
    private volatile String delivering = "";
    /** A batch is being delivered outside the lock (by one thread at a time). */
    private boolean inFlight;
    /** The position jumped while a batch was in flight: {@code jumped} runs when it ends. */
    private boolean jumpDue;
    private long position;
    private long anchorRecording;
    private long anchorWall;
    private boolean playing;
    private boolean finished;
    private double speed = 1;
    private long loopFrom = -1;
    private long loopTo = -1;
    private volatile long emitted;     // written by the one delivering thread
    /** A seek's position whose state ({@link PlayHead}) is still to be delivered, or -1. */
    private long headDue = -1;
    /**
     * Moves on each jump and each unpaced run: a state read before is stale and not delivered (an
     * unpaced run, {@link #runFor}, plays from the position for a headless tool and wants no state);
     * a batch in flight stops when it moves. Written under the lock.
     */
    private volatile long headEpoch;
    private boolean closed;
    private Thread thread;

    public Player(Recording recording, EnvelopeSink sink, PlaybackClock clock) {
        this(recording, sink, clock, () -> { });
    }

    /**
     * @param jumped run each time the position jumps instead of advancing, before anything from
     *               the new position is delivered: at once by the control (under the player's lock),
     *               or, while a batch is in flight, by the delivering thread when that batch ends
     */
    public Player(Recording recording, EnvelopeSink sink, PlaybackClock clock, Runnable jumped) {
        this(ReplaySession.of(recording), sink, clock, jumped);
    }

    /** Plays a session of one or several files (merged by time, each on the first file's clock). */
    public Player(ReplaySession session, EnvelopeSink sink, PlaybackClock clock) {
        this(session, sink, clock, () -> { });
    }

    /** @see #Player(Recording, EnvelopeSink, PlaybackClock, Runnable) */
    public Player(ReplaySession session, EnvelopeSink sink, PlaybackClock clock, Runnable jumped) {
        this.session = session;
        this.sink = sink;
        this.clock = clock;
        this.jumped = jumped;
        this.position = session.startMicros();
        this.cursor = session.cursor(position);
    }

    /** Starts the delivery thread (not needed when the caller pumps, e.g. in tests or headless). */
    public synchronized void start() {
        if (thread == null) {
            thread = new Thread(this::loop, "touchline-replay");
            thread.setDaemon(true);
            thread.start();
        }
    }

    private void loop() {
        while (true) {
            long waitNanos = pump(); // delivers outside the lock
            synchronized (this) {
                if (closed) {
                    return;
                }
                if (headDue >= 0) {
                    continue; // a seek came while pumping
                }
                try {
                    long w = playing ? Math.max(1_000_000L, Math.min(waitNanos, MAX_WAIT_NANOS)) : 0;
                    if (w == 0) {
                        wait();
                    } else {
                        wait(w / 1_000_000L, (int) (w % 1_000_000L));
                    }
                } catch (InterruptedException e) {
                    return;
                }
            }
        }
    }

    /**
     * Delivers the state at the play head after a seek (playing or paused), then every envelope
     * due by now. Returns the wall time in ns until the next one is due (Long.MAX_VALUE when paused
     * or finished).
     */
    public long pump() {
        deliverTheStateAtTheHead();
        return pumpDue();
    }

    /**
     * After a seek: the newest envelope of each kind at or before the position, read without the
     * lock (the controls stay quick while it reads), delivered unless another jump came meanwhile;
     * playing goes on after them.
     */
    private void deliverTheStateAtTheHead() {
        long at;
        long jump;
        synchronized (this) {
            if (headDue < 0 || inFlight) {
                return;
            }
            at = headDue;
            jump = headEpoch;
            headDue = -1;
        }
        List<PlayHead.Newest> state = new PlayHead(session).at(at);
        List<Due> batch = new ArrayList<>(state.size());
        synchronized (this) {
            if (jump != headEpoch || closed || inFlight) {
                return;
            }
            for (PlayHead.Newest n : state) {
                batch.add(new Due(n.envelope(), n.source()));
            }
            cursor = session.cursor(at + 1); // what the state delivered does not play again
            pending = null;
            inFlight = true;
        }
        deliverOutsideTheLock(batch, jump);
    }

    /** Takes the envelopes due by now under the lock, then delivers them outside it. */
    private long pumpDue() {
        List<Due> batch = new ArrayList<>();
        long wait;
        long epoch;
        synchronized (this) {
            if (!playing || inFlight) {
                return playing ? MAX_WAIT_NANOS : Long.MAX_VALUE;
            }
            wait = takeDue(batch);
            epoch = headEpoch;
            if (batch.isEmpty()) {
                return wait;
            }
            inFlight = true;
        }
        deliverOutsideTheLock(batch, epoch);
        return wait;
    }

    /** Under the lock: moves what is due by now into {@code batch}; returns the wait until the next is due. */
    private long takeDue(List<Due> batch) {
        long target = targetPosition();
        int taken = 0;
        int laps = 0;
        while (taken < BATCH && laps < MAX_LAPS_PER_PUMP) {
            if (pending == null) {
                pending = cursor.next();
                pendingSource = cursor.source();
                if (pending == null) {
                    if (loopFrom >= 0) {
                        target = wrap(target, Math.min(loopTo, session.endMicros()), batch);
                        laps++;
                        continue;
                    }
                    position = Math.max(position, session.endMicros());
                    playing = false;
                    finished = true;
                    return Long.MAX_VALUE;
                }
            }
            if (loopTo >= 0 && pending.timeMicros() > loopTo && target >= loopTo) {
                target = wrap(target, loopTo, batch);
                laps++;
                continue;
            }
            if (pending.timeMicros() > target) {
                break;
            }
            batch.add(new Due(pending, pendingSource));
            pending = null;
            taken++;
        }
        position = Math.max(position, Math.min(target, session.endMicros()));
        if (taken >= BATCH || pending == null) {
            return 0;
        }
        return (long) ((pending.timeMicros() - target) * 1000 / speed);
    }

    /**
     * Delivers a batch taken under the lock (which this thread no longer holds), stopping when the
     * position jumps or the player closes; then runs a jump that came meanwhile, and lets the next
     * batch be taken. Returns how many envelopes it delivered.
     */
    private int deliverOutsideTheLock(List<Due> batch, long epoch) {
        int n = 0;
        try {
            for (Due d : batch) {
                if (headEpoch != epoch) {
                    break; // the rest is from before a jump (or a close)
                }
                if (d == JUMP) {
                    jumped.run();
                } else {
                    deliver(d.envelope(), d.source());
                    n++;
                }
            }
        } finally {
            settle();
        }
        return n;
    }

    /** After a batch: the jumps announced while it was in flight, on this thread, then the batch is over. */
    private void settle() {
        while (true) {
            synchronized (this) {
                if (!jumpDue) {
                    inFlight = false;
                    notifyAll();
                    return;
                }
                jumpDue = false;
            }
            jumped.run();
        }
    }

    /** Under the lock, after a control moved the position: {@code jumped} now, or when the batch in flight ends. */
    private void announceJump() {
        if (inFlight) {
            jumpDue = true;
        } else {
            jumped.run();
        }
    }

    /**
     * Jumps back to the loop start, carrying over the time played past {@code end}; the jump is
     * announced in the batch, after what it took before; returns the new target.
     */
    private long wrap(long target, long end, List<Due> batch) {
        long excess = Math.max(0, target - end);
        reposition(loopFrom);
        batch.add(JUMP);
        anchorWall -= (long) (excess * 1000 / speed);
        return loopFrom + excess;
    }

    private void deliver(Envelope e, String source) {
        emitted++;
        delivering = source;
        try {
            sink.accept(e.asReplayed());
        } catch (RuntimeException failed) {
            // a failing consumer must not stop the replay, but what it skipped is said
            session.note("showing a replayed envelope failed (" + failed + "); such envelopes are skipped");
        }
    }

    private long targetPosition() {
        return anchorRecording + (long) ((clock.nanoTime() - anchorWall) / 1000.0 * speed);
    }

    private void reanchor() {
        anchorRecording = position;
        anchorWall = clock.nanoTime();
    }

    private void reposition(long micros) {
        position = Math.max(session.startMicros(), Math.min(micros, session.endMicros()));
        cursor = session.cursor(position);
        pending = null;
        headEpoch++;
        reanchor();
    }

    public synchronized void play() {
        if (finished) {
            reposition(loopFrom >= 0 ? loopFrom : session.startMicros());
            announceJump();
            finished = false;
        }
        if (!playing) {
            playing = true;
            reanchor();
            notifyAll();
        }
    }

    public synchronized void pause() {
        if (playing) {
            position = Math.max(position, Math.min(targetPosition(), session.endMicros()));
            playing = false;
            notifyAll();
        }
    }

    /** Jumps to {@code timeMicros} (clamped to the recording); playing continues from there. */
    public synchronized void seek(long timeMicros) {
        reposition(timeMicros);
        announceJump();
        headDue = position;
        finished = false;
        notifyAll();
    }

    /** Seeks to the first event of {@code type} after the current position, if there is one. */
    public Optional<TimelineEvent> seekToNext(TimelineEvent.Type type) {
        List<TimelineEvent> events = events(); // may read the whole file once: not under the lock
        synchronized (this) {
            long now = position;
            Optional<TimelineEvent> next = events.stream()
                    .filter(e -> e.type() == type && e.timeMicros() > now).findFirst();
            next.ifPresent(e -> seek(e.timeMicros()));
            return next;
        }
    }

    /** Sets the speed, clamped to 0.1..50; returns the speed in effect. */
    public synchronized double setSpeed(double factor) {
        if (playing) {
            position = Math.max(position, targetPosition());
        }
        speed = Double.isNaN(factor) ? 1 : Math.max(MIN_SPEED, Math.min(MAX_SPEED, factor));
        reanchor();
        notifyAll();
        return speed;
    }

    /** Loops [fromMicros, toMicros] until {@link #clearLoop()}; jumps into the range if outside. */
    public synchronized void setLoop(long fromMicros, long toMicros) {
        if (toMicros <= fromMicros) {
            throw new IllegalArgumentException("a loop needs from < to");
        }
        loopFrom = fromMicros;
        loopTo = toMicros;
        if (position < fromMicros || position > toMicros) {
            reposition(fromMicros);
            announceJump();
        }
        notifyAll();
    }

    public synchronized void clearLoop() {
        loopFrom = -1;
        loopTo = -1;
    }

    /** Delivers everything from the position to the end on the calling thread, unpaced. */
    public long runToEnd() {
        return runFor(Long.MAX_VALUE);
    }

    /**
     * Delivers up to {@code max} envelopes from the position on the calling thread, unpaced; a
     * headless run plays from the position and takes no state at the play head.
     */
    public long runFor(long max) {
        long n = 0;
        synchronized (this) {
            headDue = -1;
            headEpoch++;
        }
        while (true) {
            List<Due> batch = new ArrayList<>();
            long epoch;
            boolean ended = false;
            synchronized (this) {
                while (inFlight) { // another thread delivers: after it
                    try {
                        wait();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return n;
                    }
                }
                long taking = n;
                if (pending != null) {
                    batch.add(new Due(pending, pendingSource));
                    pending = null;
                    taking++;
                }
                int limit = (int) Math.min(BATCH, max - taking);
                int taken = 0;
                for (Envelope e = null; taken < limit && (e = cursor.next()) != null; taken++) {
                    batch.add(new Due(e, cursor.source()));
                    position = e.timeMicros();
                }
                if (taking + taken < max && taken < limit) {
                    finished = true;
                    playing = false;
                    position = session.endMicros();
                    ended = true;
                }
                epoch = headEpoch;
                inFlight = !batch.isEmpty();
            }
            if (!batch.isEmpty()) {
                n += deliverOutsideTheLock(batch, epoch);
            }
            if (n >= max || ended) {
                return n;
            }
        }
    }

    public synchronized PlayerState snapshot() {
        long pos = playing ? Math.max(position, Math.min(targetPosition(), session.endMicros())) : position;
        return new PlayerState(pos, session.startMicros(), session.endMicros(), playing, finished, speed,
                loopFrom, loopTo, emitted, session.notes());
    }

    /**
     * The recording's timeline events. The first call reads the whole file (about a second per
     * recorded hour), so a UI calls it off the FX thread; later calls return the cached list.
     */
    public List<TimelineEvent> events() {
        return session.events();
    }

    /** The files played, with their clock offsets. */
    public ReplaySession session() {
        return session;
    }

    /**
     * The name of the file the envelope being delivered comes from ("" for a single file);
     * valid inside the sink, on the delivering thread.
     */
    public String deliveringSource() {
        return delivering;
    }

    @Override
    public void close() {
        Thread t;
        synchronized (this) {
            closed = true;
            playing = false;
            headEpoch++; // a batch in flight stops after the envelope in hand
            notifyAll();
            t = thread;
        }
        if (t != null) {
            try {
                t.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
