package touchline.ui.render;

/**
 * Axis-aligned lines and rectangle outlines drawn as filled rectangles on whole pixels, by a
 * canvas ({@code g::fillRect} in its current fill colour) or a {@link Raster}. Under the software
 * renderer a stroke is anti-aliased scanline by scanline over its whole bounding box (a frame
 * outline costs about what filling the frame costs), while a pixel-aligned filled rectangle is a
 * plain fill; the result looks the same.
 */
public final class CrispLines {

    /** Fills a rectangle: x, y, width, height. */
    @FunctionalInterface
    public interface Fill {
        void rect(double x, double y, double w, double h);
    }

    private CrispLines() { }

    /** The outline of a rectangle, {@code width} pixels thick, drawn inside x, y, w, h. */
    public static void outline(Fill f, double x, double y, double w, double h, double width) {
        double x0 = Math.round(x);
        double y0 = Math.round(y);
        double x1 = Math.round(x + w);
        double y1 = Math.round(y + h);
        double t = Math.max(1, Math.round(width));
        f.rect(x0, y0, x1 - x0, t);
        f.rect(x0, y1 - t, x1 - x0, t);
        f.rect(x0, y0 + t, t, Math.max(0, y1 - y0 - 2 * t));
        f.rect(x1 - t, y0 + t, t, Math.max(0, y1 - y0 - 2 * t));
    }

    /** A horizontal line from x0 to x1 at y, one pixel thick. */
    public static void horizontal(Fill f, double x0, double x1, double y) {
        f.rect(Math.round(Math.min(x0, x1)), Math.floor(y), Math.round(Math.abs(x1 - x0)), 1);
    }

    /** A vertical line from y0 to y1 at x, one pixel thick. */
    public static void vertical(Fill f, double x, double y0, double y1) {
        f.rect(Math.floor(x), Math.round(Math.min(y0, y1)), 1, Math.round(Math.abs(y1 - y0)));
    }
}
