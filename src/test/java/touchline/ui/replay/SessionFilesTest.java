package touchline.ui.replay;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

class SessionFilesTest {

    @Test
    void filesAreSeparatedBySemicolonsAndMayCarryAnOffsetInSeconds() {
        SessionFiles f = SessionFiles.parse(" /rec/laptop.mcap ;robot3.mcap = +1.25; ;robot4.mcap=-0.3");
        assertEquals(List.of(Path.of("/rec/laptop.mcap"), Path.of("robot3.mcap"), Path.of("robot4.mcap")), f.files());
        assertEquals(Map.of(Path.of("robot3.mcap"), 1_250_000L, Path.of("robot4.mcap"), -300_000L), f.offsets());
        assertEquals("/rec/laptop.mcap; robot3.mcap=+1.250; robot4.mcap=-0.300", f.text());
        assertEquals("laptop.mcap and 2 more", f.names());
        assertEquals(f, SessionFiles.parse(f.text()));
    }

    @Test
    void addingFilesKeepsTheOnesThereAndTheirOffsets() {
        SessionFiles f = SessionFiles.parse("a.mcap; b.mcap=+2").plus(List.of(Path.of("b.mcap"), Path.of("c.mcap")));
        assertEquals("a.mcap; b.mcap=+2.000; c.mcap", f.text());
        assertEquals(List.of(), SessionFiles.parse("  ").files());
    }
}
