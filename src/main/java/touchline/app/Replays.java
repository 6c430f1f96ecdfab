package touchline.app;

import touchline.record.RecordingException;
import touchline.record.ReplaySession;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Replaying recordings into the console's stream, one replay at a time. Replayed envelopes are
 * marked: they never cause a datagram, never change match mode, and fill the model beside the
 * live robots, never merged with them; closing a replay takes its robots, options and stores
 * with it.
 */
public final class Replays {

    private final LiveField field;
    private final Naos naos;
    private final SystemClock realClock;
    private final ReplaySlot slot;

    Replays(LiveField field, Naos naos, SystemClock realClock, ReplaySlot slot) {
        this.field = field;
        this.naos = naos;
        this.realClock = realClock;
        this.slot = slot;
    }

    /**
     * Opens a recording and plays it into the replay stream (paused at its start), which the
     * read models take beside the live stream and nothing that acts on the field takes: it
     * never causes a datagram, never changes match mode, and its robots stand beside the live
     * ones, never merged with them. Each jump of the replay (a seek, a loop going round) starts its robots and stores
     * afresh.
     */
    public Replay open(Path file) throws RecordingException {
        return open(List.of(file), Map.of());
    }

    /**
     * Opens several recordings (the laptop's and robots' own logs) as one replay on one
     * timeline, as {@link #open(Path)} does one: each file's clock is moved onto the first
     * file's by the offset given in {@code offsets} (µs, the file's clock minus the first's) or
     * else by the GameController packets both files heard (this reads each file once: call it
     * off the UI thread). A robot heard in two files is one replayed robot.
     */
    public synchronized Replay open(List<Path> files, Map<Path, Long> offsets) throws RecordingException {
        close();
        ReplaySession session = ReplaySession.open(files, offsets, field.kinds());
        long start = session.startMicros();
        restartReplayedViews(start);
        Replay replay = new Replay(session, field.replayStream().publisher(), realClock, () -> {
            restartReplayedViews(start);
            field.robots().forgetReplayed();
        }).start();
        slot.set(replay);
        return replay;
    }

    public Optional<Replay> current() {
        return Optional.ofNullable(slot.get());
    }

    /** Closes the replay; its robots, options and stores go with it, live ones stay. */
    public synchronized void close() {
        Replay replay = slot.get();
        if (replay != null) {
            replay.close();
            slot.set(null);
            field.robots().forgetReplayed();
            field.options().forgetReplayed();
            restartReplayedViews(field.clock().nowMicros());
        }
    }

    /** Forgets what the faces show of a replay (the view stores and the NAO feeds) as of {@code startMicros}. */
    private void restartReplayedViews(long startMicros) {
        field.stores().restartReplay(startMicros);
        naos.restartReplay();
    }
}
