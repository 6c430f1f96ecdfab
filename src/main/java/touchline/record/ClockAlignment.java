package touchline.record;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Estimates how far one recording's clock is from another's from the GameController
 * datagrams both heard: the same bytes (packet number and content) received by two machines
 * at nearly the same instant. Pure: it gets the packets' receive times and bytes, no files.
 *
 * <p>A GameController's packet number wraps (after 256 packets, about two minutes at two a
 * second), and while nothing changes (INITIAL, a timeout) the same bytes come again, so one
 * packet of a file may share its bytes with several of the other. The estimate therefore takes
 * two passes: a rough offset where most pairs of equal packets agree (differences counted in
 * 200 ms windows; of equally full windows the one nearest zero, since two computers' clocks are
 * rarely a packet-number wrap apart), then each packet of the other file is matched to the
 * reference's packet with the same bytes nearest to where the rough offset puts it, within
 * {@link #MATCH_WINDOW_MICROS}. The offset is the median of the matched differences; the
 * agreement is the 95th percentile of the matches' distance from it.
 */
public final class ClockAlignment {

    /** A packet further than this from where the rough offset expects it is no match. */
    static final long MATCH_WINDOW_MICROS = 2_000_000;
    private static final long BIN_MICROS = 100_000;
    private static final int MAX_PAIRS = 2_000_000;

    /** One GameController datagram a recording heard: its receive time on that recording's clock, and its bytes. */
    public record Packet(long timeMicros, byte[] bytes) { }

    /**
     * How a file's clock relates to the reference's: {@code time in the file = time in the
     * reference + offsetMicros}.
     *
     * @param offsetMicros    the file's clock minus the reference's (0 when not aligned)
     * @param matches         the packets matched (0 when given or not aligned)
     * @param p95ResidualMicros 95th percentile of |difference - offset| over the matches
     * @param how             how the offset was found
     */
    public record Offset(long offsetMicros, int matches, long p95ResidualMicros, How how) {

        public static final Offset REFERENCE = new Offset(0, 0, 0, How.REFERENCE);
        public static final Offset NONE = new Offset(0, 0, 0, How.NOT_ALIGNED);

        public static Offset given(long offsetMicros) {
            return new Offset(offsetMicros, 0, 0, How.GIVEN);
        }

        /** One line for people, e.g. "+1.248 s, 412 GC packets matched, agree within 3 ms". */
        public String describe() {
            return switch (how) {
                case REFERENCE -> "reference clock";
                case GIVEN -> String.format("%+.3f s (given)", offsetMicros / 1e6);
                case NOT_ALIGNED -> "not aligned: no GameController packets in common (played with offset 0)";
                case MATCHED -> String.format("%+.3f s, %d GC packets matched, agree within %s", offsetMicros / 1e6,
                        matches, p95ResidualMicros < 1000 ? "1 ms" : Math.round(p95ResidualMicros / 1000.0) + " ms");
            };
        }
    }

    /** How an offset was found. */
    public enum How { REFERENCE, MATCHED, GIVEN, NOT_ALIGNED }

    /** The offset of {@code other}'s clock to {@code reference}'s, or {@link Offset#NONE} without common packets. */
    public Offset estimate(List<Packet> reference, List<Packet> other) {
        Map<ByteBuffer, List<Long>> ref = byBytes(reference);
        Map<ByteBuffer, List<Long>> oth = byBytes(other);
        Map<Long, Integer> bins = new HashMap<>();
        int pairs = 0;
        for (Map.Entry<ByteBuffer, List<Long>> e : oth.entrySet()) {
            List<Long> r = ref.get(e.getKey());
            if (r == null) {
                continue;
            }
            for (long t : e.getValue()) {
                for (long tr : r) {
                    if (pairs++ < MAX_PAIRS) {
                        bins.merge(Math.floorDiv(t - tr, BIN_MICROS), 1, Integer::sum);
                    }
                }
            }
        }
        if (bins.isEmpty()) {
            return Offset.NONE;
        }
        long bestBin = 0;
        int bestCount = -1;
        for (long bin : bins.keySet()) {
            int count = bins.get(bin) + bins.getOrDefault(bin + 1, 0);
            if (count > bestCount || (count == bestCount && Math.abs(bin) < Math.abs(bestBin))) {
                bestBin = bin;
                bestCount = count;
            }
        }
        long guess = (bestBin + 1) * BIN_MICROS;
        List<Long> diffs = new ArrayList<>();
        for (Map.Entry<ByteBuffer, List<Long>> e : oth.entrySet()) {
            List<Long> r = ref.get(e.getKey());
            if (r == null) {
                continue;
            }
            for (long t : e.getValue()) {
                long best = Long.MAX_VALUE;
                for (long tr : r) {
                    long d = t - tr;
                    if (best == Long.MAX_VALUE || Math.abs(d - guess) < Math.abs(best - guess)) {
                        best = d;
                    }
                }
                if (Math.abs(best - guess) <= MATCH_WINDOW_MICROS) {
                    diffs.add(best);
                }
            }
        }
        long offset = median(diffs);
        long[] residuals = diffs.stream().mapToLong(d -> Math.abs(d - offset)).sorted().toArray();
        long p95 = residuals[Math.min(residuals.length - 1, (int) Math.ceil(0.95 * residuals.length) - 1)];
        return new Offset(offset, diffs.size(), p95, How.MATCHED);
    }

    private static Map<ByteBuffer, List<Long>> byBytes(List<Packet> packets) {
        Map<ByteBuffer, List<Long>> m = new HashMap<>();
        for (Packet p : packets) {
            m.computeIfAbsent(ByteBuffer.wrap(p.bytes()), k -> new ArrayList<>()).add(p.timeMicros());
        }
        return m;
    }

    private static long median(List<Long> values) {
        long[] v = values.stream().mapToLong(Long::longValue).toArray();
        Arrays.sort(v);
        int n = v.length;
        return n % 2 == 1 ? v[n / 2] : Math.floorDiv(v[n / 2 - 1] + v[n / 2], 2);
    }
}
