package touchline.ui.render;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.plots.PlotView;

class ColumnDecimationTest {

    @Test
    void aBurstShrinksToAtMostFourPointsPerColumnKeepingEachColumnsExtremes() {
        int n = 10_000;
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = i / (double) n;
            y[i] = Math.sin(i / 37.0) * (1 + i % 7);
        }
        int columns = 100;
        ColumnDecimation d = new ColumnDecimation();
        d.run(x, y, 0, n, 0, 1, columns);
        assertTrue(d.size() <= 4 * columns, "size " + d.size());
        assertTrue(d.size() >= 2 * columns, "size " + d.size());
        for (int c = 0; c < columns; c++) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                if ((int) Math.floor(x[i] * columns) == c) {
                    min = Math.min(min, y[i]);
                    max = Math.max(max, y[i]);
                }
            }
            double kmin = Double.POSITIVE_INFINITY;
            double kmax = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < d.size(); i++) {
                if ((int) Math.floor(d.xs()[i] * columns) == c) {
                    kmin = Math.min(kmin, d.ys()[i]);
                    kmax = Math.max(kmax, d.ys()[i]);
                }
            }
            assertEquals(min, kmin, 0, "column " + c + " min");
            assertEquals(max, kmax, 0, "column " + c + " max");
        }
        for (int i = 1; i < d.size(); i++) {
            assertTrue(d.xs()[i] >= d.xs()[i - 1], "kept in time order at " + i);
        }
    }

    @Test
    void aNonFiniteValueBecomesOneGapBetweenTheRunsAroundIt() {
        double[] x = {0, 1, 2, 3, 4, 5, 6};
        double[] y = {1, 2, Double.NaN, Double.POSITIVE_INFINITY, 3, 4, 5};
        ColumnDecimation d = new ColumnDecimation();
        d.run(x, y, 0, x.length, 0, 6, 600);
        assertEquals(6, d.size());
        assertEquals(2, d.ys()[1]);
        assertTrue(Double.isNaN(d.ys()[2]), "gap marker");
        assertEquals(3, d.ys()[3]);
        assertEquals(5, d.ys()[5]);
    }

    @Test
    void fewPointsPassUnchangedAndOnlyTheRangeAskedForIsRead() {
        double[] x = {0, 1, 2, 3, 4};
        double[] y = {5, 6, 7, 8, 9};
        ColumnDecimation d = new ColumnDecimation();
        d.run(x, y, 1, 4, 0, 4, 400);
        assertEquals(3, d.size());
        assertEquals(6, d.ys()[0]);
        assertEquals(8, d.ys()[2]);
    }

    @Test
    void windowStartIsFoundByBinarySearch() {
        double[] x = {0, 1, 2, 3, 4, 0};
        assertEquals(0, PlotView.firstAtOrAfter(x, 5, -1));
        assertEquals(2, PlotView.firstAtOrAfter(x, 5, 1.5));
        assertEquals(5, PlotView.firstAtOrAfter(x, 5, 10));
        assertEquals(2, PlotView.niceStep(1.3), 1e-12);
        assertEquals(0.5, PlotView.niceStep(0.31), 1e-12);
    }
}
