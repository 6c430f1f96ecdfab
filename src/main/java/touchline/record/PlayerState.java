package touchline.record;

import java.util.List;

/**
 * What a timeline shows about a {@link Player} at one instant. Times are microseconds
 * since the epoch, like Envelope times; loop bounds are -1 when no loop is set.
 */
public record PlayerState(long positionMicros, long startMicros, long endMicros, boolean playing, boolean finished,
                          double speed, long loopFromMicros, long loopToMicros, long emitted, ReplayNotes notes) {

    /** The notes as sentences, as {@code replay} prints them. */
    public List<String> problems() {
        return notes.lines();
    }

    public long durationMicros() {
        return endMicros - startMicros;
    }
}
