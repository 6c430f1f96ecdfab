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

    private static final Path HSL20 = Path.of("src/test/resources/golden/gamecontroller/hsl20");

    private static Envelope gc(long t, String file, String error) throws Exception {
        return new Envelope(t, Direction.IN, Channel.GAMECONTROLLER, null, Envelope.NO_ROBOT, "gc.hsl20", null,
                Files.readAllBytes(HSL20.resolve(file)), error);
    }

    @Test
    void anHslVersion20GameGivesItsStateChangesAndThreeGoals() throws Exception {
        List<Path> packets;
        try (Stream<Path> files = Files.list(HSL20)) {
            packets = files.map(Path::getFileName).map(Path::toString)
                    .filter(f -> f.matches("\\d\\d-.*\\.bin") && !f.contains("monitor")).sorted().map(Path::of).toList();
        }
        assertEquals(54, packets.size());
        EventDetector detector = new EventDetector();
        long t = 0;
        for (Path p : packets) {
            detector.accept(gc(t += 1_000_000, p.toString(), null));
        }
        List<TimelineEvent> events = detector.finish();
        List<String> goals = events.stream().filter(e -> e.type() == TimelineEvent.Type.GOAL)
                .map(TimelineEvent::label).toList();
        assertEquals(List.of("GC: goal for team 5 (5 1:0 14)", "GC: goal for team 14 (5 1:1 14)",
                "GC: goal for team 5 (14 1:2 5)"), goals);
        List<String> states = events.stream().filter(e -> e.type() == TimelineEvent.Type.STATE_CHANGE)
                .map(TimelineEvent::label).toList();
        assertEquals("GC: INITIAL → READY", states.get(0));
        assertEquals("GC: READY → FINISHED", states.get(states.size() - 1));
    }

    @Test
    void theMonitorsTrueDataWinsOverTheFakeSetRobotsSee() throws Exception {
        EventDetector detector = new EventDetector();
        detector.accept(gc(1, "04-set.bin", null));
        detector.accept(gc(2, "05-playing-delayed.monitor.bin", null));
        detector.accept(gc(3, "05-playing-delayed.bin", null));
        detector.accept(gc(4, "06-playing-delayed-after-5s.bin", null));
        detector.accept(gc(5, "06-playing-delayed-after-5s.monitor.bin", null));
        // unsolicited true data (not registered) was published with an error: not believed
        detector.accept(gc(6, "05-playing-delayed.monitor.bin", "monitor true data (RGTD) from 10.0.0.1, but ..."));
        detector.accept(gc(7, "07-playing-after-delay.bin", null));
        List<String> states = detector.finish().stream().filter(e -> e.type() == TimelineEvent.Type.STATE_CHANGE)
                .map(e -> e.timeMicros() + " " + e.label()).toList();
        assertEquals(List.of("2 GC: SET → PLAYING"), states);
    }

    /** The numbered game-state packets (not the monitors' true data) of a golden directory, one a second. */
    private static List<TimelineEvent> eventsOf(String dir, String kind) throws Exception {
        Path golden = Path.of("src/test/resources/golden/gamecontroller", dir);
        List<Path> packets;
        try (Stream<Path> files = Files.list(golden)) {
            packets = files.map(Path::getFileName).map(Path::toString)
                    .filter(f -> f.matches("\\d\\d-.*\\.bin") && !f.contains("monitor")).sorted()
                    .map(golden::resolve).toList();
        }
        EventDetector detector = new EventDetector();
        long t = 0;
        for (Path p : packets) {
            detector.accept(new Envelope(t += 1_000_000, Direction.IN, Channel.GAMECONTROLLER, null, Envelope.NO_ROBOT,
                    kind, null, Files.readAllBytes(p), null));
        }
        return detector.finish();
    }

    private static List<String> labels(List<TimelineEvent> events, TimelineEvent.Type type) {
        return events.stream().filter(e -> e.type() == type).map(e -> e.timeMicros() / 1_000_000 + " " + e.label())
                .toList();
    }

    @Test
    void anHslVersion19GameGivesItsStateChangesGoalsAndPenalties() throws Exception {
        List<TimelineEvent> events = eventsOf("hsl19", "gc.hsl19");
        // the file names say what happened: 13-goal-team5, 33-goal-team14, 50-goal-team5 (the 1st file is at 1 s)
        assertEquals(List.of("14 GC: goal for team 5 (5 1:0 14)", "34 GC: goal for team 14 (5 1:1 14)",
                "51 GC: goal for team 5 (14 1:2 5)"), labels(events, TimelineEvent.Type.GOAL));
        // 18-motion-in-set-team14-player2, 21-pushing-team14-player3, 26-arms-hands-team5-player2,
        // 31-incapable-robot-team5-player4
        assertEquals(List.of("19 GC: team 14 player 2 penalised: motion in set",
                "22 GC: team 14 player 3 penalised: pushing",
                "27 GC: team 5 player 2 penalised: playing with arms hands",
                "32 GC: team 5 player 4 penalised: incapable robot"), labels(events, TimelineEvent.Type.PENALTY));
        List<String> states = labels(events, TimelineEvent.Type.STATE_CHANGE);
        assertEquals("2 GC: INITIAL → READY", states.get(0));
        assertTrue(states.contains("36 GC: READY → FINISHED"), "35-finished-first-half: " + states);
    }

    @Test
    void anHslVersion20GameGivesItsPenalties() throws Exception {
        List<String> penalties = labels(eventsOf("hsl20", "gc.hsl20"), TimelineEvent.Type.PENALTY);
        assertTrue(penalties.contains("23 GC: team 14 player 3 penalised: pushing"), penalties.toString());
    }

    private static Envelope robot(long t, int id) {
        return new Envelope(t, Direction.IN, Channel.FUMANOID, null, id, "status", null, new byte[0], null);
    }

    /**
     * Issue 36 item 5: in play robots send once a second, so a robot is lost only after five of those
     * (1.2 s between its datagrams was "lost" on every beat); outside play after 1 s as before (a robot
     * that sends faster in play, as the sample's do, is judged by its own rate: SampleRecordingTest).
     */
    @Test
    void aRobotIsJudgedLostByTheGamesRate() throws Exception {
        EventDetector detector = new EventDetector();
        detector.accept(gc(0, "00-initial.bin", null));
        long t = 0;
        for (int i = 0; i < 3; i++) {
            detector.accept(robot(t += 200_000, 3)); // five a second outside play
        }
        detector.accept(robot(t += 1_200_000, 3)); // silent 1.2 s before play: lost
        detector.accept(gc(t += 100_000, "07-playing-after-delay.bin", null));
        for (int i = 0; i < 10; i++) {
            detector.accept(robot(t += 1_200_000, 3)); // once a second (and a bit) in play: never lost
        }
        long before = t;
        detector.accept(robot(t += 6_000_000, 3)); // six seconds silent in play: lost
        List<TimelineEvent> lost = detector.finish().stream().filter(e -> e.type() == TimelineEvent.Type.ROBOT_LOST).toList();
        assertEquals(2, lost.size(), lost.toString());
        assertEquals(600_000 + EventDetector.LOST_AFTER_MICROS, lost.get(0).timeMicros());
        assertEquals(before + 5_000_000, lost.get(1).timeMicros(), "five once-a-second periods");
        assertEquals(3, lost.get(1).robotId());
    }
}
