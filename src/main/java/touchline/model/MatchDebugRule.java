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
 * The league's debug rule measured for every robot heard (issue 40): while a robot says READY,
 * SET or PLAYING (in its Status or its match digest's Status), its datagrams to the console are
 * counted per period, the biggest one's size and IP fragments kept, and a warning raised when
 * it breaks the profile: two datagrams within half a period or more than one a period over the
 * last ten periods (too often), a datagram above the profile's size (too big), more IP fragments
 * than the profile allows. Only whole datagrams count, never the parts of a digest.
 */
public final class MatchDebugRule implements EnvelopeSink {

    /** Periods the rate is measured over. */
    static final int WINDOW_PERIODS = 10;
    /** Data bytes per IP fragment on a 1500-byte MTU (1500 less the 20-byte IPv4 header). */
    static final int FRAGMENT_BYTES = 1480;
    static final int UDP_HEADER = 8;
    private static final int KEPT = 64;

    /** What the rule allows: one datagram per {@code periodMicros}, up to {@code maxBytes} (0: no limit) in {@code maxFragments} (0: no limit). */
    public record Limits(long periodMicros, int maxBytes, int maxFragments) {

        /** HSL 2026 (samples/profiles/hsl-2026.properties): one a second, 64 kB, and Touchline's one fragment. */
        public static final Limits HSL_2026 = new Limits(1_000_000L, 65507, 1);

        /** The profile's figures; a figure it does not know is no limit (and nothing is flagged for it). */
        public static Limits of(RuleProfile profile) {
            long period = valueOr0(profile.debugPeriodMillis()) * 1000L;
            return new Limits(period, (int) valueOr0(profile.maxDebugPacketBytes()),
                    (int) valueOr0(profile.maxDebugFragments()));
        }

        private static long valueOr0(RuleLimit limit) {
            return limit.known() ? limit.value() : 0;
        }
    }

    /**
     * One robot as measured: whether it is in play, its datagrams per period, the biggest
     * datagram (UDP payload bytes) and its IP fragments, and what it breaks (empty: nothing).
     */
    public record Reading(int robotId, boolean inPlay, double perPeriod, int biggestBytes, int fragments,
                          List<String> warnings) {

        /** "1.0/period, biggest 412 B (1 fragment)" or "not in play". */
        public String describe() {
            if (!inPlay) {
                return "not in play";
            }
            return String.format("%.1f/period, biggest %d B (%d fragment%s)", perPeriod, biggestBytes, fragments,
                    fragments == 1 ? "" : "s") + (warnings.isEmpty() ? "" : ": " + String.join("; ", warnings));
        }
    }

    private final MicrosClock clock;
    private volatile Limits limits;
    private final Map<Integer, PerRobot> robots = new TreeMap<>();

    public MatchDebugRule(MicrosClock clock, Limits limits) {
        this.clock = clock;
        this.limits = limits;
    }

    /** The rule of another profile from now on (the budget guard's, when a team is guarded). */
    public void use(Limits limits) {
        this.limits = limits;
    }

    public Limits limits() {
        return limits;
    }

    /** IP fragments a UDP datagram of {@code payloadBytes} takes on a 1500-byte MTU. */
    public static int fragments(int payloadBytes) {
        return (payloadBytes + UDP_HEADER + FRAGMENT_BYTES - 1) / FRAGMENT_BYTES;
    }

    @Override
    public void accept(Envelope e) {
        if (e.replayed() || e.matchPart() || e.channel() != Channel.FUMANOID || e.direction() != Direction.IN
                || e.robotId() == Envelope.NO_ROBOT || e.isMalformed()) {
            return;
        }
        String state = reportedState(e);
        synchronized (this) {
            PerRobot r = robots.computeIfAbsent(e.robotId(), id -> new PerRobot());
            if (state != null) {
                r.inPlay = GameControlData.isPlay(GameControlData.stateCode(state));
            }
            if (r.inPlay) {
                r.add(e.timeMicros(), e.size());
            } else {
                r.count = 0;
            }
        }
    }

    private static String reportedState(Envelope e) {
        Fumanoid.Status status = e.extension(Fumanoid.status);
        if (status == null) {
            Fumanoid.MatchDigest digest = e.extension(Fumanoid.matchDigest);
            status = digest == null || !digest.hasStatus() ? null : digest.getStatus();
        }
        return status == null || !status.hasGameState() ? null : status.getGameState();
    }

    /** Every robot heard, by number. */
    public synchronized List<Reading> readings() {
        List<Reading> out = new ArrayList<>();
        long now = clock.nowMicros();
        Limits l = limits;
        robots.forEach((id, r) -> out.add(r.reading(id, now, l)));
        return out;
    }

    /** The robots breaking the rule now. */
    public List<Reading> broken() {
        return readings().stream().filter(r -> !r.warnings().isEmpty()).toList();
    }

    /** One robot's reading; not in play when it was never heard. */
    public synchronized Reading reading(int robotId) {
        PerRobot r = robots.get(robotId);
        return r == null ? new Reading(robotId, false, 0, 0, 0, List.of()) : r.reading(robotId, clock.nowMicros(), limits);
    }

    /** The last {@link #KEPT} in-play datagrams of one robot: arrival times and sizes, in a ring. */
    private static final class PerRobot {
        boolean inPlay;
        final long[] times = new long[KEPT];
        final int[] sizes = new int[KEPT];
        int next;
        int count;

        void add(long time, int size) {
            times[next] = time;
            sizes[next] = size;
            next = (next + 1) % KEPT;
            count = Math.min(count + 1, KEPT);
        }

        Reading reading(int id, long now, Limits l) {
            if (!inPlay) {
                return new Reading(id, false, 0, 0, 0, List.of());
            }
            long period = l.periodMicros() > 0 ? l.periodMicros() : 1_000_000L;
            long from = now - WINDOW_PERIODS * period;
            int inWindow = 0;
            int biggest = 0;
            long first = Long.MAX_VALUE;
            long previous = Long.MIN_VALUE;
            long closest = Long.MAX_VALUE;
            for (int k = count; k > 0; k--) { // oldest first
                int i = Math.floorMod(next - k, KEPT);
                if (times[i] < from) {
                    continue;
                }
                inWindow++;
                biggest = Math.max(biggest, sizes[i]);
                first = Math.min(first, times[i]);
                if (previous != Long.MIN_VALUE) {
                    closest = Math.min(closest, times[i] - previous);
                }
                previous = times[i];
            }
            long span = inWindow == 0 ? period : Math.max(period, now - first);
            double perPeriod = inWindow * (double) period / span;
            int fragments = biggest == 0 ? 0 : fragments(biggest);
            List<String> warnings = new ArrayList<>();
            if (l.periodMicros() > 0 && closest < period / 2) {
                warnings.add(String.format("too often: two datagrams %d ms apart (one per %d ms allowed)",
                        closest / 1000, period / 1000));
            } else if (l.periodMicros() > 0 && now - first >= WINDOW_PERIODS / 2 * period && perPeriod > 1.2) {
                warnings.add(String.format("too often: %.1f datagrams per period (one per %d ms allowed)", perPeriod,
                        period / 1000));
            }
            if (l.maxBytes() > 0 && biggest > l.maxBytes()) {
                warnings.add("too big: " + biggest + " B (at most " + l.maxBytes() + " B)");
            }
            if (l.maxFragments() > 0 && fragments > l.maxFragments()) {
                warnings.add(fragments + " IP fragments (at most " + l.maxFragments() + ")");
            }
            return new Reading(id, true, perPeriod, biggest, fragments, List.copyOf(warnings));
        }
    }
}
