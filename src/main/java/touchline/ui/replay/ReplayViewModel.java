package touchline.ui.replay;

import touchline.app.Replays;
import touchline.record.PlayerState;
import touchline.record.RecordingException;
import touchline.app.Replay;
import touchline.record.ReplayNotes;
import touchline.record.TimelineEvent;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * What the Replay view decides, without JavaFX: which files to open (or why not), the position
 * line, the loop's A and B marks, the notes as list lines and the aligned files. The view binds
 * these to its controls and runs the slow calls on its work queue.
 */
final class ReplayViewModel {

    /** A loop B pressed: the loop to set, or the reason there is none ({@code refusal} non-null). */
    record LoopB(long fromMicros, long toMicros, String refusal) { }

    private final Replays replays;
    private long loopA = -1;

    ReplayViewModel(Replays replays) {
        this.replays = replays;
    }

    /** The replay open now, if any. */
    Optional<Replay> current() {
        return replays.current();
    }

    /** The files typed in the path field, or the message saying why they cannot be opened. */
    static Optional<String> refusal(String pathText) {
        try {
            return SessionFiles.parse(pathText).files().isEmpty()
                    ? Optional.of("Type or choose a recording to open.") : Optional.empty();
        } catch (java.nio.file.InvalidPathException e) {
            return Optional.of("Not a file name: " + e.getMessage());
        }
    }

    /** Opens the session named by the path field (slow: the work queue's thread). */
    void open(SessionFiles chosen) throws RecordingException {
        replays.open(chosen.files(), chosen.offsets());
    }

    /** Closes the open replay (the work queue's thread). */
    void closeReplay() {
        replays.close();
    }

    /** Marks A at the position; returns the loop line. */
    String markA(PlayerState state) {
        loopA = state.positionMicros();
        return "A at " + TimelineCanvas.clock(loopA - state.startMicros()) + ", now set B";
    }

    /** Marks B at the position: the loop from A to B (either order), or why not. */
    LoopB markB(PlayerState state) {
        if (loopA < 0) {
            return new LoopB(-1, -1, "Set A first");
        }
        long from = Math.min(loopA, state.positionMicros());
        long to = Math.max(loopA, state.positionMicros());
        if (to <= from) {
            return new LoopB(-1, -1, "A and B are the same time");
        }
        loopA = -1;
        return new LoopB(from, to, null);
    }

    /** Forgets a mark A (the loop was cleared or another replay opened). */
    void clearMark() {
        loopA = -1;
    }

    /** The loop line while a loop plays and no A is being marked; empty otherwise. */
    Optional<String> loopLine(PlayerState state) {
        if (state == null || state.loopFromMicros() < 0 || loopA >= 0) {
            return Optional.empty();
        }
        return Optional.of("Loop " + TimelineCanvas.clock(state.loopFromMicros() - state.startMicros()) + "–"
                + TimelineCanvas.clock(state.loopToMicros() - state.startMicros()));
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
