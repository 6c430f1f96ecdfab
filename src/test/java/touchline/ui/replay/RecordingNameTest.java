package touchline.ui.replay;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.time.ZoneOffset;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The default recording name takes the time the recording starts, on a manual clock. */
class RecordingNameTest {

    private static final long NINE = 1_796_461_200L * 1_000_000L; // 2026-12-05 09:00:00 UTC
    private final long[] now = {NINE};
    private final RecordingName name = new RecordingName(() -> now[0], ZoneOffset.UTC);

    @Test
    void anUntouchedFieldTakesTheTimeOfTheStartNotOfTheViewsOpening() {
        String offered = name.offer();
        assertEquals("recordings/touchline-2026-12-05-090000.mcap", offered);
        now[0] += 5 * 3_600_000_000L + 62_000_000L; // the view stayed open until the afternoon's game
        assertEquals(Path.of("recordings/touchline-2026-12-05-140102.mcap"), name.forStart(offered));
        assertEquals(Path.of("recordings/touchline-2026-12-05-140102.mcap"), name.forStart("  "));
    }

    @Test
    void aTypedNameIsKept() {
        name.offer();
        now[0] += 60_000_000L;
        assertEquals(Path.of("games/final.mcap"), name.forStart("games/final.mcap "));
    }
}
