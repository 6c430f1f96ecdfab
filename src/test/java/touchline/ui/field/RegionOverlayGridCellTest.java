package touchline.ui.field;

import javafx.scene.paint.Color;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.render.ColorClasses;

class RegionOverlayGridCellTest {

    /** A grid cell is opaque (a plain store in software rendering) and shows what the translucent fill showed. */
    @Test
    void aGridCellIsItsClassColourMixedOverTheBackgroundAndOpaque() {
        Color back = RegionOverlayView.BACKGROUND;
        for (int c = 0; c < ColorClasses.count() + 2; c++) { // unknown classes too
            Color cell = RegionOverlayView.gridCell(c);
            Color k = ColorClasses.color(c);
            double a = RegionOverlayView.GRID_OPACITY;
            assertTrue(cell.isOpaque(), "class " + c);
            assertEquals(back.getRed() * (1 - a) + k.getRed() * a, cell.getRed(), 1e-6, "class " + c);
            assertEquals(back.getGreen() * (1 - a) + k.getGreen() * a, cell.getGreen(), 1e-6, "class " + c);
            assertEquals(back.getBlue() * (1 - a) + k.getBlue() * a, cell.getBlue(), 1e-6, "class " + c);
        }
    }
}
