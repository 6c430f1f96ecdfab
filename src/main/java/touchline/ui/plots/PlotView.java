package touchline.ui.plots;

import touchline.model.store.Latest;
import touchline.model.store.PlotStore;
import touchline.proto.Fumanoid;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.Set;
import touchline.ui.render.PlotDrawing;

/**
 * Line plot of one option's series in one picture ({@link PlotDrawing}): the last
 * {@link PlotDrawing#WINDOW_SECONDS} s, x in seconds since the console started. The plot store
 * already skipped non-finite points and decimated bursts; the status line says how many.
 * Any other numeric field of any message is plotted by {@link FieldPlotView}.
 */
public final class PlotView extends SourcedView {

    private final PlotDrawing plot = new PlotDrawing(() -> dirty = true);
    /** The last snapshot drawn, whose arrays the next one reuses. */
    private PlotStore.Snapshot last;

    public PlotView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.PLOT_VALUE), source);
        plot.node().setId("plot-canvas");
        root.setCenter(plot.node());
    }

    @Override
    protected void empty() {
        plot.empty();
    }

    @Override
    protected String draw(Latest latest) {
        PlotStore.Snapshot s = stores().plots().snapshot(latest.robotId(), latest.option(), last);
        if (s == null) {
            return "no plot data";
        }
        last = s; // drawn below and not kept: the next draw copies into its arrays
        int total = plot.draw(s.series());
        StringBuilder out = new StringBuilder(s.series().size() + " series · " + total + " points");
        if (s.skippedNonFinite() > 0) {
            out.append(" · ").append(s.skippedNonFinite()).append(" NaN/infinite skipped");
        }
        if (s.decimatedBursts() > 0) {
            out.append(" · ").append(s.decimatedBursts()).append(" bursts decimated");
        }
        return out.toString();
    }

    /** Index of the first x at or after {@code from} (x is oldest first). */
    public static int firstAtOrAfter(double[] x, int count, double from) {
        return PlotDrawing.firstAtOrAfter(x, count, from);
    }

    /** 1, 2 or 5 times a power of ten, at least {@code raw}. */
    public static double niceStep(double raw) {
        return PlotDrawing.niceStep(raw);
    }
}
