package touchline.record;

import java.nio.file.Path;
import java.util.List;

/**
 * Counters of a {@link Recorder} for a status bar: envelopes offered, written, dropped
 * because the hand-off queue was full, bytes written, the files, and the write failure
 * that stopped recording (null while all is well).
 */
public record RecorderStats(long received, long written, long dropped, long bytes, List<Path> files, String failure) {
}
