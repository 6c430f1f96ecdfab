package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/** The team's traffic over the last second, on a manual clock: what counts, with which headers, against whose share. */
class TrafficMeterTest {

    private static final InetSocketAddress ROBOT = new InetSocketAddress("127.0.0.1", 40001);
    private final long[] now = {1_000_000_000L};
    private final TrafficMeter meter = new TrafficMeter(() -> now[0]);

    private Envelope datagram(Direction direction, Channel channel, int robot, int bytes) {
        return new Envelope(now[0], direction, channel, ROBOT, robot, "status", null, new byte[bytes], null);
    }

    @Test
    void aRobotsDatagramCountsWithItsIpAndUdpHeaders() {
        meter.accept(datagram(Direction.IN, Channel.FUMANOID, 1, 72));
        meter.accept(datagram(Direction.IN, Channel.RELIABLE_STREAM, 1, 22));
        meter.accept(datagram(Direction.IN, Channel.GAMECONTROLLER, Envelope.NO_ROBOT, 122));

        TrafficMeter.Reading r = meter.read();
        assertEquals((72 + 28 + 22 + 28 + 122 + 28) * 8, r.teamBitsPerSecond());
        assertEquals((72 + 28 + 22 + 28) * 8, r.robotBitsPerSecond().get(1));
        assertEquals(r.teamBitsPerSecond() / 1_000_000, r.fractionOfLimit());
    }

    @Test
    void theConsolesOwnDatagramsAreCountedApartAndNaoTrafficNotAtAll() {
        meter.accept(datagram(Direction.OUT, Channel.FUMANOID, 1, 12));
        meter.accept(datagram(Direction.IN, Channel.NAO_RPC, 2, 500));
        meter.accept(datagram(Direction.IN, Channel.NAO_CAMERA, 2, 15_000));
        meter.accept(datagram(Direction.IN, Channel.LINK_EVENT, 2, 10));

        TrafficMeter.Reading r = meter.read();
        assertEquals((12 + 28) * 8, r.consoleBitsPerSecond());
        assertEquals(0, r.teamBitsPerSecond());
        assertFalse(r.robotBitsPerSecond().containsKey(2), "NAO traffic is the lab's wired link, not the field's");
    }

    @Test
    void aRobotOverItsShareOfTheLimitIsFlagged() {
        for (int i = 0; i < 100; i++) {
            meter.accept(datagram(Direction.IN, Channel.FUMANOID, 1, 672)); // 560 000 bit/s
        }
        meter.accept(datagram(Direction.IN, Channel.FUMANOID, 2, 72));

        TrafficMeter.Reading r = meter.read();
        assertEquals(500_000, r.share(), "two robots sending share the team's 1 Mbit/s");
        assertEquals(Set.of(1), r.overShare());
    }

    @Test
    void trafficLeavesTheReadingOneSecondLater() {
        meter.accept(datagram(Direction.IN, Channel.FUMANOID, 1, 72));
        now[0] += 900_000;
        assertEquals(800, meter.read().teamBitsPerSecond(), "still within the last second");

        now[0] += 100_000;
        TrafficMeter.Reading r = meter.read();
        assertEquals(0, r.teamBitsPerSecond());
        assertEquals(0, r.robotBitsPerSecond().get(1));
        assertEquals(1_000_000, r.share(), "a robot that went quiet takes no share");
    }
}
