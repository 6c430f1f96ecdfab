package touchline.ui.render;

/**
 * Reduces a series to what one pixel column can show: for each column the first, lowest,
 * highest and last point, in the order they occurred (so a drawn line looks exactly like the
 * full series at that width, spikes included), and at most four points per column however many
 * came in. A non-finite y breaks the line: it is kept as one NaN point, which the plot draws as
 * a gap. Reuses its output arrays, so a frame allocates nothing once they are big enough.
 */
final class ColumnDecimation {

    private double[] xs = new double[256];
    private double[] ys = new double[256];
    private int size;

    /** The decimated points' x (valid up to {@link #size()}); NaN in {@link #ys()} marks a gap. */
    double[] xs() {
        return xs;
    }

    double[] ys() {
        return ys;
    }

    int size() {
        return size;
    }

    /**
     * Decimates points {@code from} (inclusive) to {@code to} (exclusive) of x/y for an x range
     * {@code [x0, x1]} drawn over {@code columns} pixel columns.
     */
    void run(double[] x, double[] y, int from, int to, double x0, double x1, int columns) {
        size = 0;
        double perColumn = columns / Math.max(1e-12, x1 - x0);
        long column = Long.MIN_VALUE;
        int first = -1;
        int min = -1;
        int max = -1;
        int last = -1;
        for (int i = from; i < to; i++) {
            if (!Double.isFinite(y[i]) || !Double.isFinite(x[i])) {
                flush(x, y, first, min, max, last);
                first = -1;
                column = Long.MIN_VALUE;
                if (size > 0 && !Double.isNaN(ys[size - 1])) {
                    put(x[i], Double.NaN); // one gap marker per run of bad points
                }
                continue;
            }
            long c = (long) Math.floor((x[i] - x0) * perColumn);
            if (c != column || first < 0) {
                flush(x, y, first, min, max, last);
                column = c;
                first = i;
                min = i;
                max = i;
            } else {
                if (y[i] < y[min]) {
                    min = i;
                }
                if (y[i] > y[max]) {
                    max = i;
                }
            }
            last = i;
        }
        flush(x, y, first, min, max, last);
    }

    private void flush(double[] x, double[] y, int first, int min, int max, int last) {
        if (first < 0) {
            return;
        }
        put(x[first], y[first]);
        int a = Math.min(min, max);
        int b = Math.max(min, max);
        if (a != first) {
            put(x[a], y[a]);
        }
        if (b != first && b != a) {
            put(x[b], y[b]);
        }
        if (last != first && last != a && last != b) {
            put(x[last], y[last]);
        }
    }

    private void put(double x, double y) {
        if (size == xs.length) {
            xs = java.util.Arrays.copyOf(xs, size * 2);
            ys = java.util.Arrays.copyOf(ys, size * 2);
        }
        xs[size] = x;
        ys[size] = y;
        size++;
    }
}
