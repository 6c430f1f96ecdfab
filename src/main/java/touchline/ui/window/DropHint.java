package touchline.ui.window;

import javafx.scene.layout.BorderStroke;
import javafx.scene.paint.Color;
import software.coley.bentofx.control.canvas.PixelCanvas;

/**
 * The canvas over a tab group that shows where a dragged tab would go: BentoFX draws that hint in
 * a fixed red (a red target reads as an error); here in the theme's accent, with BentoFX's own
 * transparency. The accent is the looked-up colour {@code -color-accent-emphasis} of the dark or
 * light theme, read through this region's (zero-width, never painted) border, which
 * {@code touchline.css} gives the class {@code drop-hint}.
 */
final class DropHint extends PixelCanvas {

    /** BentoFX's accent when the theme's cannot be read (before the CSS applied). */
    private static final Color FALLBACK = Color.web("#1f6feb");

    DropHint() {
        getStyleClass().add("drop-hint");
    }

    @Override
    public void fillBorderedRect(double x, double y, double width, double height, int borderWidth, int fill,
                                 int border) {
        super.fillBorderedRect(x, y, width, height, borderWidth, accent(fill), accent(border));
    }

    /** The accent with the alpha of BentoFX's colour (its fill is light, its border stronger). */
    int accent(int argb) {
        Color c = FALLBACK;
        if (getBorder() != null && !getBorder().getStrokes().isEmpty()) {
            BorderStroke s = getBorder().getStrokes().get(0);
            if (s.getTopStroke() instanceof Color themed) {
                c = themed;
            }
        }
        int rgb = ((int) Math.round(c.getRed() * 255) << 16) | ((int) Math.round(c.getGreen() * 255) << 8)
                | (int) Math.round(c.getBlue() * 255);
        return (argb & 0xFF000000) | rgb;
    }
}
