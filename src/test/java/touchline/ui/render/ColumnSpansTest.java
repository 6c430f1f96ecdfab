package touchline.ui.render;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ColumnSpansTest {

    @Test
    void aSlopedSegmentCoversEachColumnItCrossesWithItsPartOfTheRise() {
        ColumnSpans s = new ColumnSpans();
        s.reset(10);
        s.line(new double[] {0, 4}, new double[] {0, 40}, 2);
        for (int c = 0; c < 4; c++) {
            assertEquals(c * 10, s.lo(c), 1e-9);
            assertEquals(c * 10 + 10, s.hi(c), 1e-9);
        }
        assertEquals(40, s.lo(4), 1e-9);
        assertFalse(s.covered(5));
    }

    @Test
    void pointsInOneColumnSpanTheirLowestToHighestAndRunsApartLeaveAGap() {
        ColumnSpans s = new ColumnSpans();
        s.reset(10);
        s.line(new double[] {2.1, 2.5, 2.9}, new double[] {5, -3, 7}, 3);
        s.line(new double[] {6.5}, new double[] {1}, 1);
        assertEquals(-3, s.lo(2), 1e-9);
        assertEquals(7, s.hi(2), 1e-9);
        assertFalse(s.covered(3), "no line across the gap");
        assertFalse(s.covered(5));
        assertTrue(s.covered(6));
        assertEquals(1, s.lo(6), 1e-9);
    }

    @Test
    void pointsOutsideThePlotAreIgnoredButTheirSegmentsStillReachIn() {
        ColumnSpans s = new ColumnSpans();
        s.reset(4);
        s.line(new double[] {-2, 2}, new double[] {0, 4}, 2);
        assertEquals(2, s.lo(0), 1e-9);
        assertEquals(3, s.hi(0), 1e-9);
        assertTrue(s.covered(2));
        assertFalse(s.covered(3));
    }
}
