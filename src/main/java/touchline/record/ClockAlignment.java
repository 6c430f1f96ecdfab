package touchline.record;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
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
    private static final int MAX_PAIRS = 1_000_000;

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
        return estimate(Packets.of(reference), Packets.of(other));
    }

    /**
     * The offset of {@code other}'s clock to {@code reference}'s, or {@link Offset#NONE} without
     * common packets. Linear in the packets (apart from sorting each packet's times): the rough
     * offset weighs at most {@link #MAX_PAIRS} pairs, those of the rarest bytes first (a packet
     * heard once in each file is one pair; bytes heard a thousand times are a million pairs and
     * are sampled evenly), and each packet is matched by a binary search among its twins.
     */
    public Offset estimate(Packets reference, Packets other) {
        Map<Long, long[]> ref = reference.byBytes();
        Map<Long, long[]> oth = other.byBytes();
        List<long[][]> common = new ArrayList<>();
        for (Map.Entry<Long, long[]> e : oth.entrySet()) {
            long[] r = ref.get(e.getKey());
            if (r != null) {
                common.add(new long[][]{r, e.getValue(), {e.getKey()}});
            }
        }
        if (common.isEmpty()) {
            return Offset.NONE;
        }
        common.sort(Comparator.<long[][]>comparingLong(c -> (long) c[0].length * c[1].length)
                .thenComparingLong(c -> c[2][0]));
        Map<Long, Integer> bins = new HashMap<>();
        long budget = MAX_PAIRS;
        for (long[][] c : common) {
            if (budget <= 0) {
                break;
            }
            long[] r = c[0];
            long[] o = c[1];
            long pairs = (long) r.length * o.length;
            int step = pairs <= budget ? 1 : (int) Math.ceil(Math.sqrt((double) pairs / budget));
            for (int i = 0; i < o.length; i += step) {
                for (int j = 0; j < r.length; j += step) {
                    bins.merge(Math.floorDiv(o[i] - r[j], BIN_MICROS), 1, Integer::sum);
                    budget--;
                }
            }
        }
        long bestBin = 0;
        int bestCount = -1;
        for (Map.Entry<Long, Integer> bin : bins.entrySet()) {
            int count = bin.getValue() + bins.getOrDefault(bin.getKey() + 1, 0);
            if (count > bestCount || (count == bestCount && Math.abs(bin.getKey()) < Math.abs(bestBin))) {
                bestBin = bin.getKey();
                bestCount = count;
            }
        }
        long guess = (bestBin + 1) * BIN_MICROS;
        long[] diffs = new long[other.size()];
        int matched = 0;
        for (long[][] c : common) {
            for (long t : c[1]) {
                long d = t - nearest(c[0], t - guess);
                if (Math.abs(d - guess) <= MATCH_WINDOW_MICROS) {
                    diffs[matched++] = d;
                }
            }
        }
        if (matched == 0) {
            return Offset.NONE;
        }
        long[] matches = Arrays.copyOf(diffs, matched);
        Arrays.sort(matches);
        long offset = matched % 2 == 1 ? matches[matched / 2]
                : Math.floorDiv(matches[matched / 2 - 1] + matches[matched / 2], 2);
        long[] residuals = Arrays.stream(matches).map(d -> Math.abs(d - offset)).sorted().toArray();
        long p95 = residuals[Math.min(residuals.length - 1, (int) Math.ceil(0.95 * residuals.length) - 1)];
        return new Offset(offset, matched, p95, How.MATCHED);
    }

    /** The time in {@code sorted} nearest to {@code target}; of two as near, the earlier. */
    private static long nearest(long[] sorted, long target) {
        int i = Arrays.binarySearch(sorted, target);
        if (i >= 0) {
            return sorted[i];
        }
        int after = -i - 1;
        if (after == 0) {
            return sorted[0];
        }
        if (after == sorted.length) {
            return sorted[after - 1];
        }
        return target - sorted[after - 1] <= sorted[after] - target ? sorted[after - 1] : sorted[after];
    }

    /**
     * The GameController packets one file heard, kept small: each packet's receive time and a
     * 64-bit hash of its bytes (16 bytes a packet, whatever its size), at most {@code max}
     * packets; those beyond are counted, not kept.
     */
    public static final class Packets {
        private final int max;
        private long[] keys = new long[64];
        private long[] times = new long[64];
        private int size;
        private long refused;

        public Packets(int max) {
            this.max = max;
        }

        static Packets of(List<Packet> packets) {
            Packets p = new Packets(packets.size());
            packets.forEach(x -> p.add(x.timeMicros(), x.bytes()));
            return p;
        }

        /** Adds a packet; false (and counted) when {@code max} are kept already. */
        public boolean add(long timeMicros, byte[] bytes) {
            if (size == max) {
                refused++;
                return false;
            }
            if (size == keys.length) {
                keys = Arrays.copyOf(keys, (int) Math.min(max, 2L * size));
                times = Arrays.copyOf(times, keys.length);
            }
            keys[size] = hash(bytes);
            times[size++] = timeMicros;
            return true;
        }

        public int size() {
            return size;
        }

        /** Packets not kept because {@code max} were. */
        public long refused() {
            return refused;
        }

        /** Each distinct packet's receive times, sorted. */
        private Map<Long, long[]> byBytes() {
            Map<Long, int[]> counts = new HashMap<>();
            for (int i = 0; i < size; i++) {
                counts.computeIfAbsent(keys[i], k -> new int[1])[0]++;
            }
            Map<Long, long[]> times = new HashMap<>();
            counts.forEach((key, n) -> times.put(key, new long[n[0]]));
            for (int i = 0; i < size; i++) {
                times.get(keys[i])[--counts.get(keys[i])[0]] = this.times[i];
            }
            times.values().forEach(Arrays::sort);
            return times;
        }

        // FNV-1a over the bytes, then a final mix: equal bytes, equal key; a collision only blurs an estimate
        private static long hash(byte[] bytes) {
            long h = 0xcbf29ce484222325L ^ bytes.length;
            for (byte b : bytes) {
                h = (h ^ (b & 0xFF)) * 0x100000001b3L;
            }
            h ^= h >>> 33;
            h *= 0xff51afd7ed558ccdL;
            return h ^ (h >>> 33);
        }
    }
}
