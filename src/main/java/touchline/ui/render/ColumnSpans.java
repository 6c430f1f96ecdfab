package touchline.ui.render;

import java.util.Arrays;

/**
 * A line rasterised into one vertical span per pixel column: the lowest and highest y the line
 * passes through in that column. The plot draws each covered column as one small filled
 * rectangle, which under the software renderer costs a fraction of stroking the same polyline
 * (an anti-aliased stroke is scanned over its whole bounding box, edge by edge). Together with
 * {@link ColumnDecimation} a series costs what the plot's width costs.
 */
final class ColumnSpans {

    private double[] lo = new double[0];
    private double[] hi = new double[0];
    private int columns;

    /** Clears every column for a plot {@code columns} pixels wide. */
    void reset(int columns) {
        this.columns = columns;
        if (lo.length < columns) {
            lo = new double[columns];
            hi = new double[columns];
        }
        Arrays.fill(lo, 0, columns, Double.POSITIVE_INFINITY);
        Arrays.fill(hi, 0, columns, Double.NEGATIVE_INFINITY);
    }

    int columns() {
        return columns;
    }

    boolean covered(int c) {
        return lo[c] <= hi[c];
    }

    double lo(int c) {
        return lo[c];
    }

    double hi(int c) {
        return hi[c];
    }

    /** Adds a connected run of points (x in columns from the plot's left edge, y in pixels). */
    void line(double[] x, double[] y, int n) {
        for (int i = 0; i < n; i++) {
            mark(x[i], y[i]);
            if (i > 0) {
                segment(x[i - 1], y[i - 1], x[i], y[i]);
            }
        }
    }

    private void segment(double xa, double ya, double xb, double yb) {
        if (xb < xa) {
            double t = xa; xa = xb; xb = t;
            t = ya; ya = yb; yb = t;
        }
        int ca = (int) Math.floor(xa);
        int cb = (int) Math.floor(xb);
        if (ca == cb) {
            mark(xa, Math.min(ya, yb));
            mark(xa, Math.max(ya, yb));
            return;
        }
        double slope = (yb - ya) / (xb - xa);
        for (int c = Math.max(ca, 0); c <= Math.min(cb, columns - 1); c++) {
            double x0 = Math.max(xa, c);
            double x1 = Math.min(xb, c + 1);
            double y0 = ya + (x0 - xa) * slope;
            double y1 = ya + (x1 - xa) * slope;
            extend(c, Math.min(y0, y1), Math.max(y0, y1));
        }
    }

    private void mark(double x, double y) {
        extend((int) Math.floor(x), y, y);
    }

    private void extend(int c, double a, double b) {
        if (c < 0 || c >= columns) {
            return;
        }
        lo[c] = Math.min(lo[c], a);
        hi[c] = Math.max(hi[c], b);
    }
}
