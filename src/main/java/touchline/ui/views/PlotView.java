package touchline.ui.views;

import io.fair_acc.chartfx.XYChart;
import io.fair_acc.chartfx.axes.spi.DefaultNumericAxis;
import io.fair_acc.dataset.spi.DoubleDataSet;
import touchline.model.store.Latest;
import touchline.model.store.PlotStore;
import touchline.proto.Fumanoid;
import touchline.ui.SourcedView;
import touchline.ui.ViewContext;
import touchline.ui.ViewSource;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * Line plot of one option's series (ChartFX), x in seconds since the console started. The
 * plot store already skipped non-finite points and decimated bursts; the status line says
 * how many.
 */
public final class PlotView extends SourcedView {

    private final XYChart chart;
    private final DefaultNumericAxis xAxis;
    private final DefaultNumericAxis yAxis;
    private final Map<String, DoubleDataSet> series = new LinkedHashMap<>();
    private int points;

    /** Seconds of history drawn. */
    static final double WINDOW_SECONDS = 10;

    public PlotView(ViewContext context, ViewSource source) {
        super(context, Set.of(Fumanoid.DebugKind.PLOT_VALUE), source);
        xAxis = new DefaultNumericAxis("time", "s");
        yAxis = new DefaultNumericAxis("value");
        // ranges are set from the data each frame: ChartFX's auto-range stuck on a first frame
        // with a single point (zero width) and never widened again
        xAxis.setAutoRanging(false);
        yAxis.setAutoRanging(false);
        chart = new XYChart(xAxis, yAxis);
        chart.setId("plot-chart");
        chart.setLegendVisible(true);
        // markers on thousands of points cost more than the lines; the lines show the shape
        chart.getRenderers().stream().filter(r -> r instanceof io.fair_acc.chartfx.renderer.spi.ErrorDataSetRenderer)
                .forEach(r -> ((io.fair_acc.chartfx.renderer.spi.ErrorDataSetRenderer) r).setDrawMarker(false));
        root.setCenter(chart);
    }

    /** Points currently drawn over all series (for tests). */
    public int points() {
        return points;
    }

    @Override
    protected void empty() {
        chart.getDatasets().clear();
        series.clear();
        points = 0;
    }

    @Override
    protected String draw(Latest latest) {
        PlotStore.Snapshot s = context.stores().plots().snapshot(latest.robotId(), latest.option());
        if (s == null) {
            return "no plot data";
        }
        int total = 0;
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        double newest = Double.NEGATIVE_INFINITY;
        for (PlotStore.SeriesData d : s.series()) {
            if (d.count() > 0) {
                newest = Math.max(newest, d.x()[d.count() - 1]);
            }
        }
        // Draw the last WINDOW_SECONDS: what a person reads off a live plot, and a tenth of the
        // points the software renderer would otherwise redraw every frame.
        double from = newest - WINDOW_SECONDS;
        for (PlotStore.SeriesData d : s.series()) {
            int start = 0;
            while (start < d.count() && d.x()[start] < from) {
                start++;
            }
            int n = d.count() - start;
            double[] x = java.util.Arrays.copyOfRange(d.x(), start, d.count());
            double[] y = java.util.Arrays.copyOfRange(d.y(), start, d.count());
            for (int i = 0; i < n; i++) {
                minX = Math.min(minX, x[i]);
                maxX = Math.max(maxX, x[i]);
                minY = Math.min(minY, y[i]);
                maxY = Math.max(maxY, y[i]);
            }
            DoubleDataSet ds = series.get(d.name());
            if (ds == null) {
                ds = new DoubleDataSet(d.name(), context.stores().plots().pointsPerSeries());
                series.put(d.name(), ds);
                chart.getDatasets().add(ds);
            }
            ds.set(x, y, n, false);
            total += n;
        }
        if (total > 0) {
            double padY = Math.max(1e-3, (maxY - minY) * 0.05);
            xAxis.set(minX, maxX > minX ? maxX : minX + 1);
            yAxis.set(minY - padY, maxY + padY);
        }
        points = total;
        StringBuilder out = new StringBuilder(s.series().size() + " series · " + total + " points");
        if (s.skippedNonFinite() > 0) {
            out.append(" · ").append(s.skippedNonFinite()).append(" NaN/infinite skipped");
        }
        if (s.decimatedBursts() > 0) {
            out.append(" · ").append(s.decimatedBursts()).append(" bursts decimated");
        }
        return out.toString();
    }
}
