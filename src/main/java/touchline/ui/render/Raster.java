package touchline.ui.render;

import java.util.Arrays;

/**
 * A view's own pixels (premultiplied ARGB, one int each, row by row), drawn in Java and shown as
 * one image ({@link touchline.ui.render.RasterPane}) by the plot and the region overlay: under JavaFX's
 * software renderer a canvas replays every one of a frame's rectangles through its rasteriser
 * (the plot: ~1 700, a span per pixel column and series), fills its background and blends itself
 * onto the window, up to 30 times a second (docs/archive/benchmarks-sessions.md, "Twentieth session").
 * Coordinates are the view's (logical) pixels; {@link #scale()} device pixels each on a
 * high-density screen. What lies under a drawing is opaque; a label's edge or a translucent fill
 * is blended over it. Drawing needs no window: testable without one.
 */
public final class Raster {

    /** A small picture drawn over the pixels, e.g. a label: premultiplied ARGB, row by row. */
    public record Sprite(int width, int height, int[] pixels) { }

    private int width;
    private int height;
    private double scale = 1;
    private int[] pixels = new int[0];

    /** Sizes the raster for a view of {@code w} × {@code h} logical pixels at {@code scale} device pixels each, in pixels of its own. */
    void resize(double w, double h, double scale) {
        size(w, h, scale);
        if (pixels.length < width * height) {
            pixels = new int[width * height];
        }
    }

    private void size(double w, double h, double scale) {
        this.scale = scale > 0 ? scale : 1;
        width = Math.max(1, (int) Math.ceil(w * this.scale));
        height = Math.max(1, (int) Math.ceil(h * this.scale));
    }

    /**
     * Starts a picture for {@code pane}: its size and scale, drawn into its pixels not on screen,
     * filled with {@code background}. {@link #show} puts it on screen.
     */
    public void begin(touchline.ui.render.RasterPane pane, int background) {
        size(pane.getWidth(), pane.getHeight(), pane.scale());
        drawInto(pane.back(width, height));
        fill(background);
    }

    /** Puts the picture drawn since {@link #begin} on {@code pane}'s screen. */
    public void show(touchline.ui.render.RasterPane pane) {
        pane.showBack(scale);
    }

    /**
     * Draws from now on into {@code target} (at least {@link #width()} × {@link #height()} long),
     * e.g. the pixels of a {@link touchline.ui.render.RasterPane} not on screen.
     */
    void drawInto(int[] target) {
        if (target.length < width * height) {
            throw new IllegalArgumentException(target.length + " pixels for " + width + " x " + height);
        }
        pixels = target;
    }

    /** Width in device pixels. */
    int width() {
        return width;
    }

    /** Height in device pixels. */
    int height() {
        return height;
    }

    public double scale() {
        return scale;
    }

    void fill(int argb) {
        Arrays.fill(pixels, 0, width * height, argb);
    }

    /** Fills the device pixels whose centres lie inside the rectangle (logical coordinates). */
    public void fillRect(double x, double y, double w, double h, int argb) {
        int x0 = clamp(Math.round(x * scale), width);
        int x1 = clamp(Math.round((x + w) * scale), width);
        int y0 = clamp(Math.round(y * scale), height);
        int y1 = clamp(Math.round((y + h) * scale), height);
        for (int row = y0; row < y1; row++) {
            Arrays.fill(pixels, row * width + x0, row * width + x1, argb);
        }
    }

    /** Blends {@code argb} at {@code opacity} (0..1) over the device pixels whose centres lie inside the rectangle. */
    public void blendRect(double x, double y, double w, double h, int argb, double opacity) {
        int alpha = (int) Math.round(Math.max(0, Math.min(1, opacity)) * 255);
        if (alpha >= 255) {
            fillRect(x, y, w, h, argb);
            return;
        }
        int x0 = clamp(Math.round(x * scale), width);
        int x1 = clamp(Math.round((x + w) * scale), width);
        int y0 = clamp(Math.round(y * scale), height);
        int y1 = clamp(Math.round((y + h) * scale), height);
        for (int row = y0; row < y1; row++) {
            for (int i = row * width + x0; i < row * width + x1; i++) {
                pixels[i] = mix(argb, pixels[i], alpha);
            }
        }
    }

    /** The outline of a rectangle, {@code thickness} logical pixels thick, inside x, y, w, h (edges rounded to pixels). */
    public void outline(double x, double y, double w, double h, double thickness, int argb) {
        CrispLines.outline((rx, ry, rw, rh) -> fillRect(rx, ry, rw, rh, argb), x, y, w, h, thickness);
    }

    /** The same outline dashed: {@code dash} logical pixels drawn, {@code gap} left, along each edge. */
    public void dashedOutline(double x, double y, double w, double h, double thickness, double dash, double gap, int argb) {
        double x0 = Math.round(x);
        double y0 = Math.round(y);
        double x1 = Math.round(x + w);
        double y1 = Math.round(y + h);
        double t = Math.max(1, Math.round(thickness));
        for (double at = x0; at < x1; at += dash + gap) {
            double len = Math.min(dash, x1 - at);
            fillRect(at, y0, len, t, argb);
            fillRect(at, y1 - t, len, t, argb);
        }
        for (double at = y0; at < y1; at += dash + gap) {
            double len = Math.min(dash, y1 - at);
            fillRect(x0, at, t, len, argb);
            fillRect(x1 - t, at, t, len, argb);
        }
    }

    /**
     * One logical pixel column from {@code top} to {@code bottom} (fractional), the two end pixels
     * blended by how much of them the span covers: what an anti-aliased renderer makes of a
     * one-pixel-wide rectangle, at the cost of a few array writes.
     */
    void fillColumn(int column, double top, double bottom, int argb) {
        int x0 = clamp(Math.round(column * scale), width);
        int x1 = clamp(Math.round((column + 1) * scale), width);
        double t = Math.max(0, top * scale);
        double b = Math.min(height, bottom * scale);
        if (x0 >= x1 || !(b > t)) {
            return;
        }
        int first = (int) Math.floor(t);
        int last = Math.min(height - 1, (int) Math.ceil(b) - 1);
        for (int y = first; y <= last; y++) {
            double coverage = Math.min(b, y + 1) - Math.max(t, y);
            int alpha = (int) Math.round(coverage * 255);
            int row = y * width;
            for (int x = x0; x < x1; x++) {
                pixels[row + x] = alpha >= 255 ? argb : mix(argb, pixels[row + x], alpha);
            }
        }
    }

    /** Draws {@code sprite} with its top-left corner at ({@code x}, {@code y}) logical, over what is there. */
    public void draw(Sprite sprite, double x, double y) {
        int left = (int) Math.round(x * scale);
        int top = (int) Math.round(y * scale);
        int[] src = sprite.pixels();
        for (int sy = Math.max(0, -top); sy < sprite.height() && top + sy < height; sy++) {
            int dRow = (top + sy) * width;
            int sRow = sy * sprite.width();
            for (int sx = Math.max(0, -left); sx < sprite.width() && left + sx < width; sx++) {
                int s = src[sRow + sx];
                int a = s >>> 24;
                if (a == 255) {
                    pixels[dRow + left + sx] = s;
                } else if (a != 0) {
                    pixels[dRow + left + sx] = over(s, pixels[dRow + left + sx]);
                }
            }
        }
    }

    /** An opaque colour: 0xFFRRGGBB from a JavaFX colour (its opacity ignored). */
    public static int opaque(javafx.scene.paint.Color c) {
        return 0xFF000000 | channel(c.getRed()) << 16 | channel(c.getGreen()) << 8 | channel(c.getBlue());
    }

    private static int channel(double v) {
        return (int) Math.round(Math.max(0, Math.min(1, v)) * 255);
    }

    /** {@code src} at {@code alpha}/255 over opaque {@code dst}. */
    static int mix(int src, int dst, int alpha) {
        int inv = 255 - alpha;
        int r = (((src >> 16) & 0xFF) * alpha + ((dst >> 16) & 0xFF) * inv + 127) / 255;
        int g = (((src >> 8) & 0xFF) * alpha + ((dst >> 8) & 0xFF) * inv + 127) / 255;
        int b = ((src & 0xFF) * alpha + (dst & 0xFF) * inv + 127) / 255;
        return 0xFF000000 | r << 16 | g << 8 | b;
    }

    /** Premultiplied {@code src} over opaque {@code dst}. */
    static int over(int src, int dst) {
        int inv = 255 - (src >>> 24);
        int r = ((src >> 16) & 0xFF) + (((dst >> 16) & 0xFF) * inv + 127) / 255;
        int g = ((src >> 8) & 0xFF) + (((dst >> 8) & 0xFF) * inv + 127) / 255;
        int b = (src & 0xFF) + ((dst & 0xFF) * inv + 127) / 255;
        return 0xFF000000 | Math.min(255, r) << 16 | Math.min(255, g) << 8 | Math.min(255, b);
    }

    private static int clamp(long v, int max) {
        return (int) Math.max(0, Math.min(max, v));
    }
}
