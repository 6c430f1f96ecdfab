package touchline.ui.render;

import javafx.scene.paint.Color;
import touchline.model.store.PlotStore;
import touchline.ui.render.RasterPane;

import java.util.List;
import java.util.Locale;

/**
 * The drawing of a line plot, shared by the option plot and the field plot: the last
 * {@link #WINDOW_SECONDS} s, a y axis per unit (or per series on request, {@link YAxes}) fitted
 * to its series, a legend with each series' colour. Each
 * series is reduced to at most four points per pixel column before drawing
 * ({@link ColumnDecimation}) and drawn as one filled span per column ({@link ColumnSpans}), so a
 * burst of 10 000 points costs what the plot's width costs; a non-finite value breaks the line.
 * Pixels of our own ({@link Raster}, labels as {@link LabelSprites}) shown as one image, rather
 * than a chart library (under the software renderer a chart's axis nodes, relayout and layers
 * cost several times the whole frame budget) or a canvas (which replays each of the frame's
 * rectangles through JavaFX's rasteriser and blends itself onto the window: docs/archive/benchmarks-sessions.md,
 * "Twentieth session").
 */
public final class PlotDrawing {

    /** Seconds of history drawn. */
    static final double WINDOW_SECONDS = 10;
    static final Color[] PALETTE = {
        Color.web("#4c9bff"), Color.web("#ff7b3a"), Color.web("#3fc46a"), Color.web("#e5534b"),
        Color.web("#b083f0"), Color.web("#d4a72c"), Color.web("#39c5cf"), Color.web("#f778ba"),
    };
    private static final double LEFT = 58;
    private static final double RIGHT = 12;
    private static final double TOP = 24;
    private static final double BOTTOM = 22;
    private static final double LINE = 1.5;
    /** Width of each y axis after the first (to the right of the plot). */
    static final double AXIS_WIDTH = 64;
    private static final Color BACKGROUND = Color.gray(0.12);
    private static final Color GRID = Color.gray(0.26);
    private static final Color LABEL = Color.gray(0.75);
    private static final Color AXIS = Color.gray(0.5);
    private static final int BACKGROUND_ARGB = Raster.opaque(BACKGROUND);
    private static final int GRID_ARGB = Raster.opaque(GRID);
    private static final int AXIS_ARGB = Raster.opaque(AXIS);
    private static final int[] PALETTE_ARGB = java.util.Arrays.stream(PALETTE).mapToInt(Raster::opaque).toArray();

    private final RasterPane pane;
    private final Raster raster = new Raster();
    private final LabelSprites labels = new LabelSprites(javafx.scene.text.Font.font(11));
    private final ColumnDecimation decimation = new ColumnDecimation();
    private final ColumnSpans spans = new ColumnSpans();
    private double[] sx = new double[256];
    private double[] sy = new double[256];
    private boolean axisPerSeries;
    private YAxes axes = new YAxes(List.of(), new int[0], false);

    /** @param resized called when the pane changed size (the owner redraws) */
    public PlotDrawing(Runnable resized) {
        pane = new RasterPane(resized);
    }

    public RasterPane node() {
        return pane;
    }

    /** One y axis per series rather than one per unit (drawn from the next frame). */
    public void axisPerSeries(boolean on) {
        axisPerSeries = on;
    }

    public void empty() {
        raster.begin(pane, BACKGROUND_ARGB);
        raster.show(pane);
    }

    /** Draws the series' last {@link #WINDOW_SECONDS} (x oldest first); returns the points in the window. */
    public int draw(List<PlotStore.SeriesData> series) {
        double newest = Double.NEGATIVE_INFINITY;
        for (PlotStore.SeriesData d : series) {
            if (d.count() > 0) {
                newest = Math.max(newest, d.x()[d.count() - 1]);
            }
        }
        // the last WINDOW_SECONDS: what a person reads off a live plot
        double from = newest - WINDOW_SECONDS;
        int[] starts = new int[series.size()];
        int total = 0;
        for (int k = 0; k < starts.length; k++) {
            PlotStore.SeriesData d = series.get(k);
            starts[k] = firstAtOrAfter(d.x(), d.count(), from);
            total += d.count() - starts[k];
        }
        axes = new YAxes(series, starts, axisPerSeries);
        double w = pane.getWidth();
        double h = pane.getHeight();
        raster.begin(pane, BACKGROUND_ARGB);
        double pw = Math.max(1, w - LEFT - RIGHT - (axes.count() - 1) * AXIS_WIDTH);
        double ph = Math.max(1, h - TOP - BOTTOM);
        if (!Double.isFinite(newest)) {
            newest = WINDOW_SECONDS;
            from = 0;
        }
        drawAxes(from, newest, pw, ph);
        for (int k = 0; k < starts.length; k++) {
            PlotStore.SeriesData d = series.get(k);
            YAxes.Axis axis = axes.of(k);
            decimation.run(d.x(), d.y(), starts[k], d.count(), from, newest, (int) Math.ceil(pw));
            drawSeries(PALETTE_ARGB[k % PALETTE.length], from, newest, axis.y0(), axis.y1(), pw, ph);
        }
        drawLegend(series, w);
        raster.show(pane);
        return total;
    }

    /** Index of the first x at or after {@code from} (x is oldest first). */
    public static int firstAtOrAfter(double[] x, int count, double from) {
        int lo = 0;
        int hi = count;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (x[mid] < from) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /**
     * Draws the decimated series as one filled span per pixel column ({@link ColumnSpans}),
     * the line broken at each gap.
     */
    private void drawSeries(int argb, double x0, double x1, double y0, double y1, double pw, double ph) {
        double[] xs = decimation.xs();
        double[] ys = decimation.ys();
        int n = decimation.size();
        if (sx.length < n) {
            sx = new double[n];
            sy = new double[n];
        }
        double fx = pw / Math.max(1e-9, x1 - x0);
        double fy = ph / (y1 - y0);
        spans.reset((int) Math.ceil(pw));
        int run = 0;
        for (int i = 0; i <= n; i++) {
            if (i == n || Double.isNaN(ys[i])) {
                spans.line(sx, sy, run);
                run = 0;
                continue;
            }
            sx[run] = (xs[i] - x0) * fx;
            sy[run] = TOP + (y1 - ys[i]) * fy;
            run++;
        }
        for (int c = 0; c < spans.columns(); c++) {
            if (spans.covered(c)) {
                // half a pixel either side: a flat line is as thick as a sloped one
                raster.fillColumn((int) LEFT + c, spans.lo(c) - LINE / 2, spans.hi(c) + LINE / 2, argb);
            }
        }
    }

    /**
     * The first y axis on the left with the grid, each further one (another unit) to the right
     * of the plot, its labels carrying the unit; the time axis below.
     */
    private void drawAxes(double x0, double x1, double pw, double ph) {
        double scale = raster.scale();
        for (int a = 0; a < axes.count(); a++) {
            YAxes.Axis axis = axes.axis(a);
            double y0 = axis.y0();
            double y1 = axis.y1();
            double yStep = niceStep((y1 - y0) / Math.max(2, ph / 40));
            double right = LEFT + pw + (a - 1) * AXIS_WIDTH;
            for (double v = Math.ceil(y0 / yStep) * yStep; v <= y1; v += yStep) {
                double y = Math.round(TOP + (y1 - v) / (y1 - y0) * ph);
                Raster.Sprite s = labels.of(axis.label(label(v, yStep)), LABEL, scale);
                if (a == 0) {
                    raster.fillRect(LEFT, y, pw, 1, GRID_ARGB); // right of the labels, left of the series
                    raster.draw(s, LEFT - 6 - s.width() / scale, y - s.height() / scale / 2); // right-aligned, centred
                } else {
                    raster.fillRect(right, y, 4, 1, AXIS_ARGB);
                    raster.draw(s, right + 6, y - s.height() / scale / 2);
                }
            }
            if (a > 0) {
                raster.fillRect(right, TOP, 1, ph, AXIS_ARGB);
            }
        }
        double xStep = niceStep((x1 - x0) / Math.max(2, pw / 70));
        for (double v = Math.ceil(x0 / xStep) * xStep; v <= x1; v += xStep) {
            double x = Math.round(LEFT + (v - x0) / (x1 - x0) * pw);
            raster.fillRect(x, TOP, 1, ph, GRID_ARGB);
            Raster.Sprite s = labels.of(label(v, xStep) + " s", LABEL, scale);
            raster.draw(s, x - s.width() / scale / 2, TOP + ph + 4); // centred under its line
        }
        raster.fillRect(LEFT, TOP, 1, ph, AXIS_ARGB);
        raster.fillRect(LEFT, TOP + ph, pw, 1, AXIS_ARGB);
    }

    private void drawLegend(List<PlotStore.SeriesData> series, double w) {
        double scale = raster.scale();
        double x = LEFT;
        for (int k = 0; k < series.size(); k++) {
            String name = series.get(k).name();
            double width = 22 + name.length() * 6.5;
            if (x + width > w && x > LEFT) {
                Raster.Sprite s = labels.of("+" + (series.size() - k) + " more", LABEL, scale);
                raster.draw(s, x, TOP / 2 - s.height() / scale / 2);
                break;
            }
            raster.fillRect(x, TOP / 2 - 1.5, 14, 3, PALETTE_ARGB[k % PALETTE.length]);
            Raster.Sprite s = labels.of(name, LABEL, scale);
            raster.draw(s, x + 18, TOP / 2 - s.height() / scale / 2);
            x += width + 10;
        }
    }

    /** 1, 2 or 5 times a power of ten, at least {@code raw}. */
    public static double niceStep(double raw) {
        if (!(raw > 0) || !Double.isFinite(raw)) {
            return 1;
        }
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        double m = raw / p;
        return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
    }

    private static String label(double v, double step) {
        if (Math.abs(v) < step * 1e-6) {
            v = 0;
        }
        int decimals = (int) Math.max(0, Math.ceil(-Math.log10(step)));
        return String.format(Locale.ROOT, "%." + Math.min(6, decimals) + "f", v);
    }
}
