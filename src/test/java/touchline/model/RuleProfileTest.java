package touchline.model;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The league profiles in samples/profiles, and what a broken profile says. */
class RuleProfileTest {

    @Test
    void everyShippedProfileReads() throws Exception {
        for (String name : new String[]{"hsl-2026", "spl-2025", "hl-2025", "lab"}) {
            RuleProfile p = RuleProfile.named(name);
            assertTrue(p.halfSeconds() > 0 && p.halves() > 0, name);
        }
        RuleProfile hsl = RuleProfile.named("hsl-2026");
        assertEquals(RuleLimit.of(12_000), hsl.teamMessageBudget());
        assertEquals(RuleLimit.of(512), hsl.maxTeamMessageBytes());
        assertEquals(RuleLimit.of(1000), hsl.debugPeriodMillis());
        assertEquals(RuleLimit.of(2000), RuleProfile.named("spl-2025").debugPeriodMillis());
        assertEquals(RuleLimit.NONE, RuleProfile.named("lab").debugPeriodMillis());
        assertEquals(RuleLimit.UNKNOWN, hsl.trafficBitsPerSecond());
        assertEquals(RuleLimit.of(1_000_000), RuleProfile.named("hl-2025").trafficBitsPerSecond());
        assertEquals(RuleLimit.NONE, RuleProfile.named("lab").teamMessageBudget());
    }

    @Test
    void aProfileWrittenWithPacketsPerSecondStillReads(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("old.properties");
        Files.writeString(file, "name = Old\nteam-messages.budget = none\nteam-messages.max-bytes = none\n"
                + "debug.packets-per-second = 2\nhalf.seconds = 600\nhalves = 2\ntraffic.bits-per-second = none\n");
        assertEquals(RuleLimit.of(500), RuleProfile.load(file).debugPeriodMillis());
    }

    @Test
    void aBrokenProfileNamesTheFileAndTheKey(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("broken.properties");
        Files.writeString(file, "name = Broken\nteam-messages.budget = lots\n");
        RuleProfileException e = assertThrows(RuleProfileException.class, () -> RuleProfile.load(file));
        assertTrue(e.getMessage().contains("team-messages.budget") && e.getMessage().contains("lots"), e.getMessage());
        RuleProfileException missing = assertThrows(RuleProfileException.class, () -> RuleProfile.named("nope"));
        assertTrue(missing.getMessage().contains("hsl-2026"), missing.getMessage());
    }
}
