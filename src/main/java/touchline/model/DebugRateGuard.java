package touchline.model;

import touchline.proto.Fumanoid;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Flags robots that send more debug packets to the base station during play than the league
 * profile allows (HSL 2026: one a second per robot; the lab's 200 ms keep-alive is five times
 * that). A robot is in play while its own status says READY, SET or PLAYING; its rate is
 * measured over the last ten seconds, so a single early or late packet does not flag it.
 * Subscribed to the live stream only: a replay's packets are last match's.
 */
public final class DebugRateGuard implements EnvelopeSink {

    private static final long WINDOW_MICROS = 10_000_000;
    private static final int BUCKETS = 5;

    /** A robot over the limit: its number, rate and the game state it reported. */
    public record OverLimit(int robotId, double perSecond, String gameState) {
        public String describe() {
            return String.format("robot %d sends %.1f debug packets/s in %s", robotId, perSecond, gameState);
        }
    }

    private final MicrosClock clock;
    private final RuleLimit limit;
    private final Map<Integer, Counts> robots = new TreeMap<>();

    public DebugRateGuard(MicrosClock clock, RuleProfile profile) {
        this.clock = clock;
        this.limit = profile.debugPacketsPerSecond();
    }

    public RuleLimit limit() {
        return limit;
    }

    @Override
    public synchronized void accept(Envelope e) {
        if (e.channel() != Channel.FUMANOID || e.direction() != Direction.IN
                || e.robotId() == Envelope.NO_ROBOT || e.isMalformed()) {
            return;
        }
        Counts c = robots.computeIfAbsent(e.robotId(), id -> new Counts());
        c.add(e.timeMicros());
        Fumanoid.Status status = e.extension(Fumanoid.status);
        if (status != null) {
            c.gameState = status.getGameState();
        }
    }

    /** The robots in play above the profile's limit now; empty when the profile has no (known) limit. */
    public synchronized List<OverLimit> overLimit() {
        List<OverLimit> over = new ArrayList<>();
        if (!limit.known()) {
            return over;
        }
        long now = clock.nowMicros();
        for (Map.Entry<Integer, Counts> r : robots.entrySet()) {
            Counts c = r.getValue();
            double perSecond = c.perSecond(now);
            if (GameControlData.isPlay(GameControlData.stateCode(c.gameState)) && perSecond > limit.value()) {
                over.add(new OverLimit(r.getKey(), perSecond, c.gameState));
            }
        }
        return over;
    }

    /** One robot's packets in the last ten seconds (two-second buckets) and its reported game state. */
    private static final class Counts {
        final TimeBuckets packets = new TimeBuckets(WINDOW_MICROS, BUCKETS);
        String gameState;

        void add(long now) {
            packets.add(now);
        }

        double perSecond(long now) {
            return packets.perSecondOfFullBuckets(now);
        }
    }
}
