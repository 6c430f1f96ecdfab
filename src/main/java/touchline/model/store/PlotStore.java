package touchline.model.store;

import touchline.proto.Fumanoid;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Plot history: per robot, option and series a ring of points, x in seconds since the store
 * started. Points that are not finite (NaN, infinity) are skipped and counted so the plot can
 * say so. A message carrying a burst of more than {@link #BURST_LIMIT} samples of one series
 * is decimated to per-bucket minimum and maximum, which keeps the burst's envelope visible
 * while costing a bounded number of points.
 */
public final class PlotStore implements EnvelopeSink {

    public static final int DEFAULT_POINTS = 4_000;
    public static final int BURST_LIMIT = 512;

    /** What a plot view copies out once per frame. */
    public record SeriesData(String name, double[] x, double[] y, int count) { }

    /** A plot's series plus its bad-input counters. */
    public record Snapshot(List<SeriesData> series, long skippedNonFinite, long decimatedBursts, long version,
                           long lastTimeMicros) { }

    private static final class Plot {
        final Map<String, SeriesRing> series = new LinkedHashMap<>();
        long skipped;
        long bursts;
        long version;
        long lastTimeMicros;

        /** A plot made after a {@link #restart} carries on from the store's version, so a view sees it changed. */
        Plot(long version) {
            this.version = version;
        }
    }

    private final int pointsPerSeries;
    private long originMicros;
    private final Map<LatestValues.Key, Plot> plots = new HashMap<>();
    private long version;
    private final touchline.model.Utf8Names names = new touchline.model.Utf8Names();
    /** The series of the message being added (guarded by this store's lock, like the plots). */
    private final String[] seriesNames = new String[16];
    private int seriesCount;

    public PlotStore(int pointsPerSeries, long originMicros) {
        this.pointsPerSeries = pointsPerSeries;
        this.originMicros = originMicros;
    }

    @Override
    public void accept(Envelope e) {
        Fumanoid.DebugPlot plot = e.direction() == Direction.IN ? e.extension(Fumanoid.debugPlot) : null;
        if (plot != null) {
            add(e.robotId(), plot, e.timeMicros());
        }
    }

    synchronized void add(int robotId, Fumanoid.DebugPlot p, long timeMicros) {
        Plot plot = plots.computeIfAbsent(new LatestValues.Key(robotId, names.of(p.getOptionBytes())),
                k -> new Plot(version));
        double x = (timeMicros - originMicros) / 1e6;
        if (oneSamplePerSeries(p)) {
            // the usual message (one value per series): straight into the rings, nothing allocated
            for (int i = 0; i < seriesCount; i++) {
                double v = p.getSamples(i).getValue();
                if (!Double.isFinite(v)) {
                    plot.skipped++;
                    continue;
                }
                ring(plot, seriesNames[i]).add(x, v);
            }
            plot.version++;
            plot.lastTimeMicros = timeMicros;
            version++;
            return;
        }
        Map<String, List<Double>> bySeries = new LinkedHashMap<>();
        for (Fumanoid.PlotSample s : p.getSamplesList()) {
            double v = s.getValue();
            if (!Double.isFinite(v)) {
                plot.skipped++;
                continue;
            }
            bySeries.computeIfAbsent(names.of(s.getSeriesBytes()), k -> new ArrayList<>()).add(v);
        }
        for (Map.Entry<String, List<Double>> s : bySeries.entrySet()) {
            SeriesRing ring = ring(plot, s.getKey());
            List<Double> values = s.getValue();
            if (values.size() == 1) {
                ring.add(x, values.get(0));
                continue;
            }
            double from = Double.isNaN(ring.lastX) ? x - 1e-3 : Math.min(ring.lastX, x);
            if (values.size() > BURST_LIMIT) {
                plot.bursts++;
                addDecimated(ring, values, from, x);
            } else {
                for (int i = 0; i < values.size(); i++) {
                    ring.add(from + (x - from) * (i + 1) / values.size(), values.get(i));
                }
            }
        }
        plot.version++;
        plot.lastTimeMicros = timeMicros;
        version++;
    }

    private SeriesRing ring(Plot plot, String series) {
        SeriesRing ring = plot.series.get(series);
        if (ring == null) {
            ring = new SeriesRing(pointsPerSeries);
            plot.series.put(series, ring);
        }
        return ring;
    }

    /**
     * True when no series occurs twice (and the message is no burst); then the names of its
     * samples are in {@link #seriesNames}, {@link #seriesCount} of them. The names come from
     * {@link #names}: a series name is decoded once, not once per sample.
     */
    private boolean oneSamplePerSeries(Fumanoid.DebugPlot p) {
        int n = p.getSamplesCount();
        if (n > seriesNames.length) {
            return false; // a burst: grouped and spread over time below
        }
        for (int i = 0; i < n; i++) {
            String name = names.of(p.getSamples(i).getSeriesBytes());
            for (int j = 0; j < i; j++) {
                if (name.equals(seriesNames[j])) {
                    return false;
                }
            }
            seriesNames[i] = name;
        }
        seriesCount = n;
        return true;
    }

    /** Min and max of each of BURST_LIMIT/2 buckets, spread evenly between the previous point and now. */
    private static void addDecimated(SeriesRing ring, List<Double> values, double from, double to) {
        int buckets = BURST_LIMIT / 2;
        int n = values.size();
        for (int b = 0; b < buckets; b++) {
            int lo = (int) ((long) b * n / buckets);
            int hi = (int) ((long) (b + 1) * n / buckets);
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            int minAt = lo;
            int maxAt = lo;
            for (int i = lo; i < hi; i++) {
                double v = values.get(i);
                if (v < min) { min = v; minAt = i; }
                if (v > max) { max = v; maxAt = i; }
            }
            double x0 = from + (to - from) * (b + 0.5) / buckets;
            double x1 = from + (to - from) * (b + 1.0) / buckets;
            // keep the order in which the extremes occurred so the shape reads right
            ring.add(x0, minAt <= maxAt ? min : max);
            ring.add(x1, minAt <= maxAt ? max : min);
        }
    }

    /**
     * Drops every plot and counts times from {@code originMicros} from now on (a replay jumped:
     * the plots show what was played since, as if played from there). Versions keep growing.
     */
    public synchronized void restart(long originMicros) {
        plots.clear();
        this.originMicros = originMicros;
        version++;
    }

    /** Copies one plot's series; {@code null} when the robot never sent that option. */
    public Snapshot snapshot(int robotId, String option) {
        return snapshot(robotId, option, null);
    }

    /**
     * The same, copying into the arrays of an earlier snapshot that the caller no longer reads
     * ({@code reuse}, may be null): a plot redrawn ten times a second then makes no garbage
     * (4 000 points of five series were 320 kB per redraw).
     */
    public synchronized Snapshot snapshot(int robotId, String option, Snapshot reuse) {
        Plot plot = plots.get(new LatestValues.Key(robotId, option));
        if (plot == null) {
            return null;
        }
        List<SeriesData> out = new ArrayList<>();
        for (Map.Entry<String, SeriesRing> s : plot.series.entrySet()) {
            double[][] xy = new double[2][];
            if (reuse != null && out.size() < reuse.series().size()) {
                xy[0] = reuse.series().get(out.size()).x();
                xy[1] = reuse.series().get(out.size()).y();
            }
            int n = s.getValue().copyTo(xy);
            out.add(new SeriesData(s.getKey(), xy[0], xy[1], n));
        }
        return new Snapshot(out, plot.skipped, plot.bursts, plot.version, plot.lastTimeMicros);
    }

    /** Version of one plot (0 when absent): a view copies only when this moved. */
    public synchronized long version(int robotId, String option) {
        Plot plot = plots.get(new LatestValues.Key(robotId, option));
        return plot == null ? 0 : plot.version;
    }

    public synchronized long version() {
        return version;
    }

    public int pointsPerSeries() {
        return pointsPerSeries;
    }
}
