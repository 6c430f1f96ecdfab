package touchline.record;

import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Events from the real HL v12 packets of a whole match (the GameController golden vectors). */
class EventDetectorTest {

    private static final Path GOLDEN = Path.of("src/test/resources/golden/gamecontroller/hl12");

    @Test
    void aMatchOfRealGameControllerPacketsGivesItsStateChangesAndOneGoal() throws Exception {
        List<Path> packets;
        try (Stream<Path> files = Files.list(GOLDEN)) {
            packets = files.filter(f -> f.toString().endsWith(".bin")).sorted().toList();
        }
        EventDetector detector = new EventDetector();
        long t = 0;
        for (Path p : packets) {
            detector.accept(new Envelope(t += 1_000_000, Direction.IN, Channel.GAMECONTROLLER, null, Envelope.NO_ROBOT,
                    "gc.hl12", null, Files.readAllBytes(p), null));
        }
        // a corrupt packet in between changes nothing
        detector.accept(new Envelope(t + 1, Direction.IN, Channel.GAMECONTROLLER, null, Envelope.NO_ROBOT, "gc.hl12",
                null, new byte[]{'R', 'G', 'm', 'e', 12}, null));
        List<TimelineEvent> events = detector.finish();
        List<TimelineEvent> goals = events.stream().filter(e -> e.type() == TimelineEvent.Type.GOAL).toList();
        assertEquals(1, goals.size(), "the teams swapping slots at half time is no goal: " + goals);
        assertEquals(7_000_000, goals.get(0).timeMicros(), "06-goal-team13");
        assertTrue(goals.get(0).label().contains("team 13"), goals.get(0).label());
        List<String> states = events.stream().filter(e -> e.type() == TimelineEvent.Type.STATE_CHANGE)
                .map(TimelineEvent::label).toList();
        assertEquals(15, states.size(), states.toString());
        assertEquals("GC: INITIAL → READY", states.get(0));
        assertEquals("GC: PLAYING → FINISHED", states.get(states.size() - 1));
    }
}
