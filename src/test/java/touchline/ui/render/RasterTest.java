package touchline.ui.render;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The plot's own pixels: spans with blended ends, clipped rectangles, labels drawn over. */
class RasterTest {

    private static final int BLACK = 0xFF000000;
    private static final int WHITE = 0xFFFFFFFF;

    /** What each raster drew into: the pixels a pane would put on screen ({@link Raster#drawInto}). */
    private final java.util.Map<Raster, int[]> drawn = new java.util.IdentityHashMap<>();

    private Raster raster(int w, int h, double scale) {
        Raster r = new Raster();
        r.resize(w, h, scale);
        int[] target = new int[r.width() * r.height()];
        r.drawInto(target);
        drawn.put(r, target);
        r.fill(BLACK);
        return r;
    }

    /** One device pixel as drawn. */
    private int pixel(Raster r, int x, int y) {
        return drawn.get(r)[y * r.width() + x];
    }

    @Test
    void aColumnCoversItsPixelsAndBlendsItsEndsByCoverage() {
        Raster r = raster(8, 20, 1);
        r.fillColumn(3, 10.25, 12.75, WHITE);
        assertEquals(BLACK, pixel(r, 3, 9));
        assertEquals(0xFFBFBFBF, pixel(r, 3, 10), "three quarters of the top pixel");
        assertEquals(WHITE, pixel(r, 3, 11));
        assertEquals(0xFFBFBFBF, pixel(r, 3, 12), "three quarters of the bottom pixel");
        assertEquals(BLACK, pixel(r, 3, 13));
        assertEquals(BLACK, pixel(r, 2, 11), "one column wide");
        assertEquals(BLACK, pixel(r, 4, 11));
    }

    @Test
    void aThinSpanInsideOnePixelBlendsThatPixelOnly() {
        Raster r = raster(4, 4, 1);
        r.fillColumn(1, 2.25, 2.75, WHITE);
        assertEquals(0xFF808080, pixel(r, 1, 2), "half a pixel covered");
        assertEquals(BLACK, pixel(r, 1, 1));
        assertEquals(BLACK, pixel(r, 1, 3));
    }

    @Test
    void drawingOutsideTheRasterIsClippedNotAnError() {
        Raster r = raster(6, 6, 1);
        r.fillRect(-10, 4, 100, 5, WHITE);
        r.fillColumn(9, -3, 50, WHITE);
        r.fillColumn(-1, -3, 50, WHITE);
        r.draw(new Raster.Sprite(3, 3, new int[] {WHITE, WHITE, WHITE, WHITE, WHITE, WHITE, WHITE, WHITE, WHITE}), 4, -1);
        for (int x = 0; x < 6; x++) {
            assertEquals(WHITE, pixel(r, x, 4));
            assertEquals(WHITE, pixel(r, x, 5));
            assertEquals(x >= 4 ? WHITE : BLACK, pixel(r, x, 0), "the sprite's rows inside the raster, x " + x);
            assertEquals(x >= 4 ? WHITE : BLACK, pixel(r, x, 1));
            assertEquals(BLACK, pixel(r, x, 2));
        }
    }

    @Test
    void aSpriteIsDrawnOverWhatIsThereByItsOwnCoverage() {
        Raster r = raster(4, 1, 1);
        r.fillRect(0, 0, 4, 1, 0xFF204060);
        int halfWhite = 0x80808080; // premultiplied: white at half coverage
        r.draw(new Raster.Sprite(3, 1, new int[] {0, halfWhite, WHITE}), 1, 0);
        assertEquals(0xFF204060, pixel(r, 0, 0));
        assertEquals(0xFF204060, pixel(r, 1, 0), "a transparent pixel leaves the background");
        assertEquals(0xFF90A0B0, pixel(r, 2, 0), "half white over the background");
        assertEquals(WHITE, pixel(r, 3, 0));
    }

    @Test
    void aTranslucentFillIsMixedWithWhatIsUnderIt() {
        Raster r = raster(4, 2, 1);
        r.fillRect(0, 0, 4, 2, 0xFF204060);
        r.blendRect(1, 0, 2, 1, WHITE, 0.5);
        assertEquals(0xFF204060, pixel(r, 0, 0));
        assertEquals(0xFF90A0B0, pixel(r, 1, 0), "half white over the fill");
        assertEquals(0xFF90A0B0, pixel(r, 2, 0));
        assertEquals(0xFF204060, pixel(r, 3, 0));
        assertEquals(0xFF204060, pixel(r, 1, 1), "one row high");
    }

    @Test
    void anOutlineIsDrawnInsideItsRectangleAndADashedOneLeavesGaps() {
        Raster r = raster(20, 20, 1);
        r.outline(2, 2, 10, 10, 2, WHITE);
        assertEquals(WHITE, pixel(r, 2, 2));
        assertEquals(WHITE, pixel(r, 3, 6), "left edge, two pixels thick");
        assertEquals(BLACK, pixel(r, 4, 6), "inside left empty");
        assertEquals(WHITE, pixel(r, 11, 11));
        assertEquals(BLACK, pixel(r, 12, 12), "nothing outside");

        Raster d = raster(20, 20, 1);
        d.dashedOutline(0, 0, 20, 20, 2, 6, 4, WHITE);
        String top = "";
        for (int x = 0; x < 18; x++) { // the right edge's first dash fills the corner
            top += pixel(d, x, 0) == WHITE ? "#" : ".";
        }
        assertEquals("######....######..", top, "six drawn, four left, along the top edge");
        assertEquals(WHITE, pixel(d, 19, 2), "the right edge starts with a dash");
        assertEquals(BLACK, pixel(d, 19, 7), "then a gap");
    }

    @Test
    void onAHighDensityScreenALogicalPixelIsScaleDevicePixels() {
        Raster r = raster(5, 5, 2);
        assertEquals(10, r.width());
        assertEquals(10, r.height());
        r.fillColumn(2, 1, 3, WHITE);
        for (int y = 0; y < 10; y++) {
            for (int x = 0; x < 10; x++) {
                boolean in = (x == 4 || x == 5) && y >= 2 && y < 6;
                assertEquals(in ? WHITE : BLACK, pixel(r, x, y), x + "," + y);
            }
        }
    }
}
