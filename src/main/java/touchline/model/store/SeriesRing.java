package touchline.model.store;

/**
 * One plot series as a fixed-size ring of (x, y) points; the oldest points fall off. Not
 * thread-safe by itself: {@link PlotStore} guards it.
 */
final class SeriesRing {

    private final double[] xs;
    private final double[] ys;
    private int start;
    private int size;
    double lastX = Double.NaN;

    SeriesRing(int capacity) {
        xs = new double[capacity];
        ys = new double[capacity];
    }

    void add(double x, double y) {
        int i = (start + size) % xs.length;
        xs[i] = x;
        ys[i] = y;
        if (size < xs.length) {
            size++;
        } else {
            start = (start + 1) % xs.length;
        }
        lastX = x;
    }

    int size() {
        return size;
    }

    /** Copies the points oldest first into the arrays (grown when too small); returns the count. */
    int copyTo(double[][] xy) {
        if (xy[0] == null || xy[0].length < size) {
            xy[0] = new double[xs.length];
            xy[1] = new double[xs.length];
        }
        for (int k = 0; k < size; k++) {
            int i = (start + k) % xs.length;
            xy[0][k] = xs[i];
            xy[1][k] = ys[i];
        }
        return size;
    }
}
