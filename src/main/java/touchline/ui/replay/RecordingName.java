package touchline.ui.replay;

import touchline.transport.MicrosClock;

import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Locale;

/**
 * The file a recording goes to: what the user typed, or, while the field still holds the name
 * it was given (or nothing), {@code recordings/touchline-<date-time>.mcap} with the time the
 * recording starts, not the time the view opened (a view left open all day named the evening's
 * game after the morning).
 */
final class RecordingName {

    static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyy-MM-dd-HHmmss", Locale.ROOT);

    private final MicrosClock clock;
    private final ZoneId zone;
    private String offered = "";

    RecordingName(MicrosClock clock, ZoneId zone) {
        this.clock = clock;
        this.zone = zone;
    }

    /** A name for the field now; remembered, so starting with it untouched takes the start's time. */
    String offer() {
        offered = at(clock.nowMicros()).toString();
        return offered;
    }

    /** The file for a recording starting now, given the field's text. */
    Path forStart(String typed) {
        String text = typed == null ? "" : typed.strip();
        return text.isEmpty() || text.equals(offered) ? at(clock.nowMicros()) : Path.of(text);
    }

    private Path at(long micros) {
        LocalDateTime now = LocalDateTime.ofInstant(java.time.Instant.EPOCH.plusNanos(micros * 1000), zone);
        return Path.of("recordings", "touchline-" + STAMP.format(now) + ".mcap");
    }
}
