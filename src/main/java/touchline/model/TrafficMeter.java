package touchline.model;

import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.util.HashMap;
import java.util.Map;

/**
 * The team's traffic against the league's limit: every datagram robots send (FUmanoids,
 * reliable stream, GameController returns), counted with its IPv4 + UDP headers, over the
 * last second; a robot is flagged when it uses more than its share of the limit.
 */
public final class TrafficMeter implements EnvelopeSink {

    /** 1 Mbit/s: the most a team may use on the field network. */
    public static final double TEAM_LIMIT_BITS_PER_SECOND = 1_000_000;
    static final int IP_UDP_HEADER_BYTES = 28;

    private final MicrosClock clock;
    private final RateWindow team = new RateWindow();
    private final RateWindow console = new RateWindow();
    private final Map<Integer, RateWindow> perRobot = new HashMap<>();

    /** The team's load at one moment. */
    public record Reading(double teamBitsPerSecond, double consoleBitsPerSecond, double share,
                          Map<Integer, Double> robotBitsPerSecond, java.util.Set<Integer> overShare) {

        public double fractionOfLimit() {
            return teamBitsPerSecond / TEAM_LIMIT_BITS_PER_SECOND;
        }
    }

    public TrafficMeter(MicrosClock clock) {
        this.clock = clock;
    }

    @Override
    public synchronized void accept(Envelope e) {
        if (e.channel() == Channel.NAO_RPC || e.channel() == Channel.NAO_CAMERA || e.channel() == Channel.LINK_EVENT) {
            return; // NAO traffic runs over the lab's wired link, not the field's Wi-Fi budget
        }
        int onAir = e.size() + IP_UDP_HEADER_BYTES;
        if (e.direction() == Direction.OUT) {
            console.add(e.timeMicros(), onAir);
            return;
        }
        team.add(e.timeMicros(), onAir);
        if (e.robotId() >= 0) {
            perRobot.computeIfAbsent(e.robotId(), k -> new RateWindow()).add(e.timeMicros(), onAir);
        }
    }

    public synchronized Reading read() {
        long now = clock.nowMicros();
        Map<Integer, Double> robots = new HashMap<>();
        java.util.Set<Integer> over = new java.util.TreeSet<>();
        int active = 0;
        for (Map.Entry<Integer, RateWindow> r : perRobot.entrySet()) {
            double bits = r.getValue().bytesPerSecond(now) * 8;
            robots.put(r.getKey(), bits);
            if (bits > 0) {
                active++;
            }
        }
        double share = TEAM_LIMIT_BITS_PER_SECOND / Math.max(1, active);
        robots.forEach((id, bits) -> {
            if (bits > share) {
                over.add(id);
            }
        });
        return new Reading(team.bytesPerSecond(now) * 8, console.bytesPerSecond(now) * 8, share, Map.copyOf(robots), over);
    }
}
