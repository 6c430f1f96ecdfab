package touchline.ui.replay;

import touchline.app.Replay;
import touchline.app.Replays;
import touchline.app.TeamSchemas;
import touchline.record.PlayerState;
import touchline.record.RecordingException;
import touchline.record.ReplayNotes;
import touchline.record.TimelineEvent;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What the Replay view does and shows, without JavaFX: the user's actions (open files or say why
 * not, play/pause, speed, seek, next event, the loop's A and B marks, close, load a team schema),
 * each slow call run on its work queue, and per frame what to show (the message, the position
 * line, the loop line, the notes, the aligned files, the timeline's events). The view's controls
 * call the actions and bind the readouts; its refresh calls {@link #refresh} once per frame.
 */
final class ReplayViewModel implements AutoCloseable {

    /** The line under the file row: what happened last, and whether it is a failure (shown red). */
    record Message(String text, boolean failure) { }

    /** What a frame's {@link #refresh} found. */
    enum Pulled {
        /** A file operation is under way (it may hold the console or the player): nothing pulled. */
        NOTHING_WHILE_BUSY,
        /** The same replay (or none) as before, its state pulled anew. */
        STATE,
        /** Another replay (or none any more) than in the last frame. */
        NEW_REPLAY
    }

    private final Replays replays;
    private final TeamSchemas schemas;
    private final WorkQueue work;
    private final WorkQueue scans;
    private final AtomicLong pendingSeek = new AtomicLong(-1);
    private final List<String> schemaLines = new ArrayList<>();
    private final LoopMarks marks = new LoopMarks();
    private Replay shown;
    private PlayerState state;
    private List<TimelineEvent> events = List.of();
    private Message message = new Message("", false);
    /** The message speaks of the replay that is open ("Opened …", "No goal after …"): it goes with it. */
    private boolean messageOfReplay;
    private String loopText = "";

    ReplayViewModel(Replays replays, TeamSchemas schemas) {
        this.replays = replays;
        this.schemas = schemas;
        this.work = new WorkQueue("touchline-replay-view", this::fail);
        this.scans = new WorkQueue("touchline-replay-events", this::fail);
    }

    /** The queue for the view's slow file work (the recording panel's too: one thread, in order). */
    WorkQueue work() {
        return work;
    }

    /** The replay open now, if any. */
    Optional<Replay> current() {
        return replays.current();
    }

    // ---- actions (FX thread); anything slow goes to the work queue ----

    /**
     * Opens the file(s) typed in the path field (paused at the start): several, separated by
     * {@code ;}, play as one session on one timeline ({@link SessionFiles}).
     */
    void open(String pathText) {
        Optional<String> refusal = refusal(pathText);
        if (refusal.isPresent()) {
            fail(refusal.get());
            return;
        }
        SessionFiles chosen = SessionFiles.parse(pathText);
        String names = chosen.names();
        say("Opening " + names + (chosen.files().size() > 1 ? " (aligning their clocks) …" : " …"));
        work.run(() -> {
            try {
                replays.open(chosen.files(), chosen.offsets());
                work.handOff(() -> sayOfReplay("Opened " + names + "."));
            } catch (RecordingException e) {
                work.handOff(() -> fail("Cannot replay " + names + ": " + e.getMessage()));
            }
        });
    }

    /** Closes the open replay. */
    void closeReplay() {
        work.run(replays::close);
    }

    /** Pauses a playing replay; plays a paused one at {@code speed} (null: as it was). */
    void playOrPause(Double speed) {
        Replay r = shown;
        if (r == null) {
            return;
        }
        boolean playing = state != null && state.playing();
        work.run(() -> {
            if (playing) {
                r.pause();
            } else {
                if (speed != null) {
                    r.setSpeed(speed);
                }
                r.play();
            }
        });
    }

    void setSpeed(Double speed) {
        Replay r = shown;
        if (r != null && speed != null) {
            work.run(() -> r.setSpeed(speed));
        }
    }

    /** Seeks to the next event of {@code type}, or says there is none. */
    void next(TimelineEvent.Type type) {
        Replay r = shown;
        if (r == null) {
            return;
        }
        work.run(() -> {
            if (r.seekToNext(type).isEmpty()) {
                work.handOff(() -> sayOfReplay(noneAfter(type)));
            }
        });
    }

    /** Seeks (coalesced: a drag asks many times, the player only seeks to the newest). */
    void seek(long micros) {
        Replay r = shown;
        if (r == null) {
            return;
        }
        if (pendingSeek.getAndSet(micros) < 0) {
            work.run(() -> {
                long t = pendingSeek.getAndSet(-1);
                if (t >= 0) {
                    r.seek(t);
                }
            });
        }
    }

    /** Marks A at the play head. */
    void markA() {
        if (state != null) {
            loopText = marks.markA(state);
        }
    }

    /** Marks B at the play head: loops from A to B, or says why not. */
    void markB() {
        Replay r = shown;
        if (r == null || state == null) {
            return;
        }
        LoopMarks.LoopB b = marks.markB(state);
        if (b.refusal() != null) {
            loopText = b.refusal();
            return;
        }
        work.run(() -> r.setLoop(b.fromMicros(), b.toMicros()));
    }

    void clearLoop() {
        Replay r = shown;
        marks.clear();
        loopText = "";
        if (r != null) {
            work.run(r::clearLoop);
        }
    }

    /** Loads a team's descriptor set in the background; {@link #schemaLines} gain what it brought. */
    void loadSchema(Path file) {
        work.run(() -> {
            List<String> lines = new ArrayList<>();
            try {
                TeamSchemas.Outcome o = schemas.load(file);
                o.extensions().forEach(x -> lines.add("✔ " + x));
                o.refusals().forEach(x -> lines.add("✖ " + x));
            } catch (RecordingException e) {
                lines.add("✖ " + e.getMessage());
            }
            work.handOff(() -> schemaLines.addAll(lines));
        });
    }

    // ---- once per frame ----

    /**
     * Applies what the background work handed over, then pulls the player's state, unless a file
     * operation is under way (it may hold the console or player lock: the FX thread never waits).
     */
    Pulled refresh() {
        work.drain();
        scans.drain();
        if (work.busy()) {
            return Pulled.NOTHING_WHILE_BUSY;
        }
        Replay r = replays.current().orElse(null);
        boolean adopted = r != shown;
        if (adopted) {
            adopt(r);
        }
        state = r == null ? null : r.state();
        marks.loopLine(state).ifPresent(line -> loopText = line);
        return adopted ? Pulled.NEW_REPLAY : Pulled.STATE;
    }

    /** A new replay (or none): its events are read on the scan thread (the first read scans the file). */
    private void adopt(Replay r) {
        shown = r;
        events = List.of();
        if (r == null && messageOfReplay) {
            say("");
        }
        marks.clear();
        loopText = "";
        if (r != null) {
            scans.run(() -> {
                List<TimelineEvent> ev = r.events();
                scans.handOff(() -> {
                    if (shown == r) {
                        events = ev;
                    }
                });
            });
        }
    }

    // ---- what the view shows ----

    Message message() {
        return message;
    }

    boolean hasReplay() {
        return shown != null;
    }

    /** The player's state as pulled in the last frame; null without a replay. */
    PlayerState state() {
        return state;
    }

    /** The timeline's events: empty until the scan thread has read them. */
    List<TimelineEvent> events() {
        return events;
    }

    String positionLine() {
        return position(state, events.size(), events.isEmpty() && shown != null && scans.busy());
    }

    String playLabel() {
        return state != null && state.playing() ? "❚❚ Pause" : "▶ Play";
    }

    /** The loop's line: the mark A, a refusal, or the loop that plays. */
    String loopText() {
        return loopText;
    }

    ReplayNotes notes() {
        return state == null ? ReplayNotes.NONE : state.notes();
    }

    List<String> alignedFiles() {
        return alignedFiles(shown);
    }

    /** Every team schema line so far, oldest first. */
    List<String> schemaLines() {
        return schemaLines;
    }

    private void fail(String why) {
        message = new Message(why, true);
        messageOfReplay = false;
    }

    private void say(String text) {
        message = new Message(text, false);
        messageOfReplay = false;
    }

    /** Says something about the open replay: the message is cleared when the replay closes. */
    private void sayOfReplay(String text) {
        say(text);
        messageOfReplay = true;
    }

    @Override
    public void close() {
        work.close();
        scans.close();
    }

    // ---- the decisions, on their own ----

    /** The files typed in the path field, or the message saying why they cannot be opened. */
    static Optional<String> refusal(String pathText) {
        try {
            return SessionFiles.parse(pathText).files().isEmpty()
                    ? Optional.of("Type or choose a recording to open.") : Optional.empty();
        } catch (java.nio.file.InvalidPathException e) {
            return Optional.of("Not a file name: " + e.getMessage());
        }
    }

    /** The position line: where the replay is, how it plays, what it emitted, its events (or that they are read). */
    static String position(PlayerState state, int events, boolean readingEvents) {
        if (state == null) {
            return "No recording open.";
        }
        return TimelineCanvas.clock(state.positionMicros() - state.startMicros()) + " / "
                + TimelineCanvas.clock(state.durationMicros())
                + (state.finished() ? "  finished" : state.playing() ? "  playing at " + speedText(state.speed())
                : "  paused")
                + "  ·  " + String.format(Locale.ROOT, "%,d", state.emitted()) + " envelopes"
                + "  ·  " + (readingEvents ? "reading events…" : events + " events");
    }

    static String speedText(double s) {
        return (s == Math.rint(s) ? String.format(Locale.ROOT, "%.0f", s) : String.format(Locale.ROOT, "%.2f", s)
                .replaceAll("0+$", "")) + "×";
    }

    /** The problems list: each note a warning, each content listed but not played. */
    static List<String> noteLines(ReplayNotes notes) {
        List<String> items = new ArrayList<>(notes.lines().stream().map(s -> "⚠ " + s).toList());
        notes.contents().forEach(c -> items.add("• " + c + " (listed, not played)"));
        return items;
    }

    /** A session's files with the offset that moved each onto the first one's clock (none for one file). */
    static List<String> alignedFiles(Replay r) {
        return r == null || r.files().size() < 2 ? List.of()
                : r.files().stream().map(f -> f.name() + " " + f.offset().describe()).toList();
    }

    /** What "next event" says when there is none after the position. */
    static String noneAfter(TimelineEvent.Type type) {
        return "No " + type.name().toLowerCase(Locale.ROOT).replace('_', ' ') + " after this point.";
    }
}
