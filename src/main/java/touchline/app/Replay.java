package touchline.app;

import touchline.record.Player;
import touchline.record.PlayerState;
import touchline.record.PlaybackClock;
import touchline.record.ReplaySession;
import touchline.record.TimelineEvent;
import touchline.transport.EnvelopeSink;

import java.util.List;
import java.util.Optional;

/**
 * A recording playing into the console's replay stream, so every view shows it as it showed
 * live traffic, while nothing that acts on the live field hears it. A daemon thread pumps the player; the controls are the player's and may be
 * called from any thread (the UI's timeline calls them from the FX thread).
 */
public final class Replay implements AutoCloseable {

    private final ReplaySession session;
    private final Player player;
    private final Thread pump;
    private volatile boolean running = true;
    private final PlaybackClock clock;
    /** The player's state as last seen, and when (the clock's nanoseconds): see {@link #state()}. */
    private volatile Seen seen;

    private record Seen(PlayerState state, long nanos) { }

    /** @param jumped run when the position jumps (a seek, a loop going round), before anything plays from there */
    Replay(ReplaySession session, EnvelopeSink sink, PlaybackClock clock, Runnable jumped) {
        this.session = session;
        this.clock = clock;
        this.player = new Player(session, sink, clock, jumped);
        remember();
        this.pump = new Thread(this::loop, "touchline-replay");
        pump.setDaemon(true);
    }

    /** Starts the pump thread (the console does, once it has made the replay). */
    Replay start() {
        pump.start();
        return this;
    }

    private void loop() {
        while (running) {
            long waitNanos;
            try {
                waitNanos = player.pump();
                remember();
            } catch (RuntimeException e) {
                org.slf4j.LoggerFactory.getLogger(Replay.class).warn("replay stopped: {}", e.toString());
                return;
            }
            try {
                Thread.sleep(Math.max(1, Math.min(waitNanos > 0 ? waitNanos / 1_000_000 : 20, 20)));
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    public void play() { player.play(); remember(); }
    public void pause() { player.pause(); remember(); }
    public void seek(long timeMicros) { player.seek(timeMicros); remember(); }
    public Optional<TimelineEvent> seekToNext(TimelineEvent.Type type) {
        Optional<TimelineEvent> e = player.seekToNext(type);
        remember();
        return e;
    }
    public double setSpeed(double factor) {
        double s = player.setSpeed(factor);
        remember();
        return s;
    }
    /**
     * Delivers up to {@code max} envelopes from the position on the calling thread, as fast as
     * the consumers take them (headless tools and the replay benchmark); returns how many.
     */
    public long runFor(long max) {
        long n = player.runFor(max);
        remember();
        return n;
    }
    public void setLoop(long fromMicros, long toMicros) { player.setLoop(fromMicros, toMicros); remember(); }
    public void clearLoop() { player.clearLoop(); remember(); }

    /**
     * The player's state now, without taking the player's lock: the model's clock reads this
     * while holding model locks, and a control holds the player's lock while its jump empties the
     * model, so waiting for the player here could deadlock. The state is refreshed by the pump thread
     * (every 20 ms at most) and by every control; while playing, the position is extrapolated
     * from the last refresh at the current speed.
     */
    public PlayerState state() {
        Seen s = seen;
        PlayerState p = s.state();
        if (!p.playing()) {
            return p;
        }
        long end = p.loopToMicros() >= 0 ? p.loopToMicros() : p.endMicros();
        long pos = Math.min(end, p.positionMicros() + (long) ((clock.nanoTime() - s.nanos()) / 1000 * p.speed()));
        return new PlayerState(Math.max(p.positionMicros(), pos), p.startMicros(), p.endMicros(), true, false,
                p.speed(), p.loopFromMicros(), p.loopToMicros(), p.emitted(), p.notes());
    }

    /** Takes a fresh snapshot; serialised so an older snapshot never replaces a newer one. */
    private synchronized void remember() {
        PlayerState p = player.snapshot();
        seen = new Seen(p, clock.nanoTime());
    }

    public List<TimelineEvent> events() { return player.events(); }
    /** What could not be read from the file (a cut-off end, a corrupt chunk, a schema that does not parse). */
    public List<String> problems() { return session.notes().lines(); }
    /** The files played (one, or several on one timeline) and how each file's clock was aligned to the first's. */
    public List<ReplaySession.Part> files() { return session.parts(); }

    /** Everything to say about the files: problems, channels skipped with counts, attachments and metadata. */
    public touchline.record.ReplayNotes notes() { return session.notes(); }

    @Override
    public void close() {
        running = false;
        pump.interrupt();
        try {
            pump.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        player.close();
        session.close();
    }
}
