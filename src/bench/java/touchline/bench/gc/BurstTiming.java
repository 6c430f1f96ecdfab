package touchline.bench.gc;

import touchline.transport.gamecontroller.SendSchedule;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * What a robot sees of the HSL send schedule, from receive times and the moments play was
 * stopped: how late the datagram announcing the stop came (0 is ideal), how far the four
 * burst intervals were from 200 ms, and how far every other interval was from 500 ms.
 * Used by {@code bench gc --hsl}.
 */
public final class BurstTiming {

    private final List<Double> stopLatencyMs = new ArrayList<>();
    private final List<Double> burstDeviationMs = new ArrayList<>();
    private final List<Double> gridDeviationMs = new ArrayList<>();

    /**
     * @param receivedNanos receive times, ascending
     * @param stopNanos     when play was stopped, ascending
     * @param intervalMs    the grid's period (500)
     * @param burstMs       the burst's spacing (200)
     */
    public BurstTiming(long[] receivedNanos, long[] stopNanos, long intervalMs, long burstMs) {
        int stop = 0;
        int burstLeft = 0;
        for (int i = 0; i < receivedNanos.length; i++) {
            long t = receivedNanos[i];
            if (stop < stopNanos.length && t >= stopNanos[stop]) {
                stopLatencyMs.add((t - stopNanos[stop]) / 1e6);
                stop++;
                burstLeft = SendSchedule.BURST_DATAGRAMS - 1;
                continue;
            }
            if (i == 0) {
                continue;
            }
            double interval = (t - receivedNanos[i - 1]) / 1e6;
            if (burstLeft > 0) {
                burstDeviationMs.add(interval - burstMs);
                burstLeft--;
            } else {
                gridDeviationMs.add(interval - intervalMs);
            }
        }
    }

    public int stops() {
        return stopLatencyMs.size();
    }

    /** p99 of |deviation| of the burst intervals, ms. */
    public double burstP99() {
        return p(burstDeviationMs, 99);
    }

    /** p99 of |deviation| of the grid intervals, ms. */
    public double gridP99() {
        return p(gridDeviationMs, 99);
    }

    /** p99 of the stop-to-datagram latency, ms. */
    public double stopLatencyP99() {
        return p(stopLatencyMs, 99);
    }

    private static double p(List<Double> values, double percentile) {
        if (values.isEmpty()) {
            return Double.NaN;
        }
        double[] abs = values.stream().mapToDouble(Math::abs).sorted().toArray();
        return GcIntervalProbe.percentile(abs, percentile);
    }

    private static double max(List<Double> values) {
        return values.stream().mapToDouble(Math::abs).max().orElse(Double.NaN);
    }

    /** One line per kind of interval. */
    public String summary() {
        return String.format(Locale.ROOT, "stops %d: stop -> datagram p50 %.3f ms, p99 %.3f ms, max %.3f ms%n"
                        + "  burst intervals %d: |deviation from 200 ms| p50 %.3f ms, p99 %.3f ms, max %.3f ms%n"
                        + "  grid intervals %d: |deviation from 500 ms| p50 %.3f ms, p99 %.3f ms, max %.3f ms",
                stopLatencyMs.size(), p(stopLatencyMs, 50), p(stopLatencyMs, 99), max(stopLatencyMs),
                burstDeviationMs.size(), p(burstDeviationMs, 50), p(burstDeviationMs, 99), max(burstDeviationMs),
                gridDeviationMs.size(), p(gridDeviationMs, 50), p(gridDeviationMs, 99), max(gridDeviationMs));
    }
}
