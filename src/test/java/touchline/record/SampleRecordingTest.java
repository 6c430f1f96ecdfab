package touchline.record;

import org.junit.jupiter.api.Test;
import touchline.transport.Envelope;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** samples/demo-team.mcap, used by the user guide, stays small, clean and eventful. */
class SampleRecordingTest {

    private static final Path SAMPLE = Path.of("samples/demo-team.mcap");

    @Test
    void theSampleIsASmallCleanThreeMinuteThreeRobotMatch() throws Exception {
        assertTrue(Files.size(SAMPLE) < 2_000_000L, "under 2 MB");
        try (Recording r = Recording.open(SAMPLE)) {
            assertTrue(r.problems().isEmpty(), r.problems().toString());
            assertTrue(r.mcap().indexed());
            List<Envelope> all = RecordingFixture.readAll(r);
            Set<Integer> robots = all.stream().map(Envelope::robotId).filter(id -> id > 0).collect(Collectors.toSet());
            assertEquals(Set.of(1, 2, 3), robots);
            assertTrue(r.durationMicros() > 170_000_000L);
            assertTrue(r.events().stream().anyMatch(e -> e.type() == TimelineEvent.Type.GOAL));
            assertTrue(r.events().stream().anyMatch(e -> e.type() == TimelineEvent.Type.ROBOT_LOST && e.robotId() == 2));
        }
    }
}
