package touchline.ui.replay;

import touchline.record.PlayerState;

import java.util.Optional;

/** The loop's A and B marks as the user sets them at the play head, and the loop's line. */
final class LoopMarks {

    /** A loop B pressed: the loop to set, or the reason there is none ({@code refusal} non-null). */
    record LoopB(long fromMicros, long toMicros, String refusal) { }

    private long loopA = -1;

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
    void clear() {
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
}
