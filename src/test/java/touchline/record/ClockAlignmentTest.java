package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Clock offsets from constructed GameController packets: no files, no network. */
class ClockAlignmentTest {

    private final ClockAlignment alignment = new ClockAlignment();

    /** A GameController sending at 2 Hz: packet number (wrapping at 256) and a state that changes every {@code change} packets. */
    private static byte[] packet(int n, int change) {
        return new byte[]{'R', 'G', 'm', 'e', (byte) (n % 256), (byte) (change == 0 ? 0 : n / change)};
    }

    /**
     * What one machine heard of packets {@code from..to}: sent at 500 ms intervals, received
     * at {@code offset} on its clock plus up to {@code jitter} µs of delay, every {@code lossEvery}-th lost.
     */
    private static List<ClockAlignment.Packet> heard(int from, int to, int change, long offset, long jitter,
                                                     int lossEvery, long seed) {
        Random random = new Random(seed);
        List<ClockAlignment.Packet> out = new ArrayList<>();
        for (int n = from; n < to; n++) {
            if (lossEvery > 0 && n % lossEvery == 0) {
                continue;
            }
            long delay = jitter == 0 ? 0 : (long) (random.nextDouble() * jitter);
            out.add(new ClockAlignment.Packet(1_000_000_000L + n * 500_000L + offset + delay, packet(n, change)));
        }
        return out;
    }

    @Test
    void theOffsetIsTheMedianOfTheMatchedPacketsAndTheSpreadIsSaid() {
        List<ClockAlignment.Packet> laptop = heard(0, 1200, 40, 0, 2_000, 0, 1);
        List<ClockAlignment.Packet> robot = heard(100, 900, 40, 1_248_000, 2_000, 7, 2);
        ClockAlignment.Offset o = alignment.estimate(laptop, robot);
        assertEquals(ClockAlignment.How.MATCHED, o.how());
        assertTrue(Math.abs(o.offsetMicros() - 1_248_000) <= 1_000, "offset " + o);
        assertEquals(robot.size(), o.matches(), "every packet the robot heard was heard by the laptop too");
        assertTrue(o.p95ResidualMicros() <= 2_000 && o.p95ResidualMicros() > 0, "spread " + o);
        assertTrue(o.describe().startsWith("+1.24") && o.describe().contains(o.matches() + " GC packets matched"),
                o.describe());
    }

    @Test
    void aNegativeOffsetAndAFewLatePacketsDoNotMoveTheMedian() {
        List<ClockAlignment.Packet> laptop = heard(0, 400, 20, 0, 0, 0, 1);
        List<ClockAlignment.Packet> robot = new ArrayList<>(heard(0, 400, 20, -3_500_000, 0, 0, 2));
        for (int i = 0; i < 10; i++) { // ten packets the robot's Wi-Fi held back 400 ms
            ClockAlignment.Packet p = robot.get(i * 37);
            robot.set(i * 37, new ClockAlignment.Packet(p.timeMicros() + 400_000, p.bytes()));
        }
        ClockAlignment.Offset o = alignment.estimate(laptop, robot);
        assertEquals(-3_500_000, o.offsetMicros());
        assertEquals(400, o.matches());
        assertEquals(0, o.p95ResidualMicros(), "ten of 400 late packets are beyond the 95th percentile");
    }

    @Test
    void repeatedBytesAfterThePacketNumberWrapsMatchTheNearestNotAWrapAway() {
        // nothing changes: the same bytes every 256 packets (128 s); the robot heard only the last two minutes
        List<ClockAlignment.Packet> laptop = heard(0, 1400, 0, 0, 1_000, 0, 1);
        List<ClockAlignment.Packet> robot = heard(1160, 1400, 0, 750_000, 1_000, 0, 2);
        ClockAlignment.Offset o = alignment.estimate(laptop, robot);
        assertTrue(Math.abs(o.offsetMicros() - 750_000) <= 1_000, "offset " + o);
        assertEquals(240, o.matches());
    }

    @Test
    void withoutCommonPacketsTheFileIsNotAligned() {
        List<ClockAlignment.Packet> laptop = heard(0, 100, 10, 0, 0, 0, 1);
        List<ClockAlignment.Packet> robot = new ArrayList<>();
        for (ClockAlignment.Packet p : heard(0, 100, 10, 0, 0, 0, 1)) {
            byte[] other = p.bytes().clone();
            other[3] = 'X'; // another GameController's packets
            robot.add(new ClockAlignment.Packet(p.timeMicros(), other));
        }
        assertEquals(ClockAlignment.Offset.NONE, alignment.estimate(laptop, robot));
        assertEquals(ClockAlignment.Offset.NONE, alignment.estimate(laptop, List.of()));
        assertTrue(ClockAlignment.Offset.NONE.describe().startsWith("not aligned: no GameController packets in common"));
    }

    @Test
    // a guard only: every pair of equal packets once took 54 s for two 4.7 KB files; these are 10^12 pairs
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aMillionRepeatsOfOnePacketInEachFileAlignInLinearWork() {
        // a GameController that never changes its bytes (or a file made to repeat one), heard twice a second by both
        byte[] same = packet(7, 0);
        List<ClockAlignment.Packet> laptop = new ArrayList<>();
        List<ClockAlignment.Packet> robot = new ArrayList<>();
        for (int n = 0; n < 1_000_000; n++) {
            laptop.add(new ClockAlignment.Packet(1_000_000_000L + n * 500_000L, same));
            robot.add(new ClockAlignment.Packet(1_000_000_000L + n * 500_000L + 1_250_000, same));
        }
        ClockAlignment.Offset o = alignment.estimate(laptop, robot);
        assertEquals(1_250_000, o.offsetMicros(), o.describe());
        assertEquals(1_000_000, o.matches(), "each of the robot's packets has its twin 1.25 s earlier");
    }

    @Test
    void packetsBeyondTheBoundAreCountedNotKeptAndTheKeptOnesStillAlign() {
        ClockAlignment.Packets laptop = new ClockAlignment.Packets(300);
        ClockAlignment.Packets robot = new ClockAlignment.Packets(300);
        heard(0, 1000, 40, 0, 0, 0, 1).forEach(p -> laptop.add(p.timeMicros(), p.bytes()));
        heard(0, 1000, 40, 400_000, 0, 0, 2).forEach(p -> robot.add(p.timeMicros(), p.bytes()));
        assertEquals(300, laptop.size());
        assertEquals(700, laptop.refused());
        ClockAlignment.Offset o = alignment.estimate(laptop, robot);
        assertEquals(400_000, o.offsetMicros());
        assertEquals(300, o.matches());
    }
}
