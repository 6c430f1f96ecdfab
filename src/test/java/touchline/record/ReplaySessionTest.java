package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.protocol.MessageKinds;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Several MCAP files as one session: clocks aligned by the GameController packets both heard, merged in time order. */
class ReplaySessionTest {

    private static final long AHEAD = 1_250_000;

    @TempDir
    Path dir;

    private static Envelope at(Envelope e, long t) {
        return new Envelope(t, e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(), e.message(), e.raw(),
                e.error(), e.origin());
    }

    /** The laptop's recording of a three-robot team, and robot 3's own log (its traffic and the GC) on a clock 1.25 s ahead. */
    private List<Envelope> laptop;
    private List<Envelope> robotOnLaptopClock;

    private Path[] write(boolean robotHeardGc) throws Exception {
        laptop = RecordingFixture.team(3, 40);
        robotOnLaptopClock = laptop.stream().filter(e -> e.robotId() == 3
                || (robotHeardGc && e.channel() == Channel.GAMECONTROLLER)).toList();
        Path a = dir.resolve("laptop.mcap");
        Path b = dir.resolve("robot3.mcap");
        RecordingFixture.write(a, laptop, EnvelopeWriter.Options.defaults());
        RecordingFixture.write(b, robotOnLaptopClock.stream().map(e -> at(e, e.timeMicros() + AHEAD)).toList(),
                EnvelopeWriter.Options.defaults());
        return new Path[]{a, b};
    }

    private static List<Envelope> all(ReplaySession s, List<String> sources) {
        List<Envelope> out = new ArrayList<>();
        ReplaySession.Cursor c = s.cursor(Long.MIN_VALUE);
        for (Envelope e = c.next(); e != null; e = c.next()) {
            out.add(e);
            sources.add(c.source());
        }
        return out;
    }

    @Test
    void twoFilesAreAlignedByTheirGameControllerPacketsAndPlayInOneOrder() throws Exception {
        Path[] f = write(true);
        try (ReplaySession s = ReplaySession.open(List.of(f[0], f[1]), Map.of(), new MessageKinds())) {
            ClockAlignment.Offset o = s.parts().get(1).offset();
            assertEquals(ClockAlignment.How.MATCHED, o.how());
            assertEquals(AHEAD, o.offsetMicros());
            long gc = robotOnLaptopClock.stream().filter(e -> e.channel() == Channel.GAMECONTROLLER).count();
            assertEquals(gc, o.matches());
            assertEquals(0, o.p95ResidualMicros());
            assertEquals(ClockAlignment.How.REFERENCE, s.parts().get(0).offset().how());

            List<String> sources = new ArrayList<>();
            List<Envelope> merged = all(s, sources);
            List<Envelope> expected = new ArrayList<>(laptop);
            expected.addAll(robotOnLaptopClock);
            expected.sort(Comparator.comparingLong(Envelope::timeMicros));
            assertEquals(expected.size(), merged.size());
            for (int i = 0; i < merged.size(); i++) {
                assertEquals(expected.get(i).timeMicros(), merged.get(i).timeMicros(), "envelope " + i);
            }
            assertEquals(robotOnLaptopClock.size(), sources.stream().filter("robot3.mcap"::equals).count());
            assertEquals(laptop.get(0).timeMicros(), s.startMicros());

            // the GC heard twice gives each state change once, not once per file
            try (Recording one = Recording.open(f[0])) {
                assertEquals(one.events().stream().filter(e -> e.type() == TimelineEvent.Type.STATE_CHANGE).toList(),
                        s.events().stream().filter(e -> e.type() == TimelineEvent.Type.STATE_CHANGE).toList());
            }
        }
    }

    @Test
    void aGivenOffsetWinsAndAFileWithoutCommonPacketsPlaysUnaligned() throws Exception {
        Path[] f = write(false);
        try (ReplaySession s = ReplaySession.open(List.of(f[0], f[1]), Map.of(), new MessageKinds())) {
            assertEquals(ClockAlignment.Offset.NONE, s.parts().get(1).offset());
            List<Envelope> merged = all(s, new ArrayList<>());
            assertEquals(laptop.get(0).timeMicros(), merged.get(0).timeMicros());
            assertEquals(robotOnLaptopClock.get(robotOnLaptopClock.size() - 1).timeMicros() + AHEAD, s.endMicros(),
                    "unaligned: the robot's times as it recorded them");
        }
        try (ReplaySession s = ReplaySession.open(List.of(f[0], f[1]), Map.of(f[1], 1_000_000L), new MessageKinds())) {
            assertEquals(ClockAlignment.Offset.given(1_000_000), s.parts().get(1).offset());
            List<Envelope> merged = all(s, new ArrayList<>());
            assertTrue(merged.stream().anyMatch(e -> e.robotId() == 3
                    && e.timeMicros() == robotOnLaptopClock.get(0).timeMicros() + 250_000));
            for (int i = 1; i < merged.size(); i++) {
                assertTrue(merged.get(i - 1).timeMicros() <= merged.get(i).timeMicros(), "in time order at " + i);
            }
        }
    }

    @Test
    void aPlayerSeeksInTheMergedSession() throws Exception {
        Path[] f = write(true);
        try (ReplaySession s = ReplaySession.open(List.of(f[0], f[1]), Map.of(), new MessageKinds())) {
            List<Envelope> got = new ArrayList<>();
            List<String> from = new ArrayList<>();
            Player[] p = new Player[1];
            p[0] = new Player(s, e -> { got.add(e); from.add(p[0].deliveringSource()); }, () -> 0L);
            long target = laptop.get(0).timeMicros() + 20_000_000;
            p[0].seek(target);
            p[0].runToEnd();
            long expected = laptop.stream().filter(e -> e.timeMicros() >= target).count()
                    + robotOnLaptopClock.stream().filter(e -> e.timeMicros() >= target).count();
            assertEquals(expected, got.size());
            assertTrue(got.stream().allMatch(Envelope::replayed));
            assertTrue(from.contains("robot3.mcap") && from.contains("laptop.mcap"));
        }
    }
}
