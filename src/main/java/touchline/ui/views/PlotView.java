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
    private final Map<String, DoubleDataSet> series = new LinkedHashMap<>();
    private int points;

    public PlotView(ViewContext context, ViewSource source) {
        super(context, Set.of(Fumanoid.DebugKind.PLOT_VALUE), source);
        DefaultNumericAxis x = new DefaultNumericAxis("time", "s");
        DefaultNumericAxis y = new DefaultNumericAxis("value");
        x.setAutoRangeRounding(false);
        chart = new XYChart(x, y);
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
        for (PlotStore.SeriesData d : s.series()) {
            DoubleDataSet ds = series.get(d.name());
            if (ds == null) {
                ds = new DoubleDataSet(d.name(), context.stores().plots().pointsPerSeries());
                series.put(d.name(), ds);
                chart.getDatasets().add(ds);
            }
            ds.set(d.x(), d.y(), d.count(), true);
            total += d.count();
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
