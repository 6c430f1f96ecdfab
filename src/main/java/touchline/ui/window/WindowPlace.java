package touchline.ui.window;

import javafx.geometry.Rectangle2D;

import java.util.List;

/**
 * Where a window was and how large, in screen coordinates (window-manager frame included, as
 * JavaFX reports a stage), and whether it was maximised.
 */
public record WindowPlace(double x, double y, double width, double height, boolean maximized) {

    /** How much of the window's top edge must be on a screen to grab it with the mouse. */
    private static final double GRIP_WIDTH = 120;
    private static final double GRIP_HEIGHT = 40;
    /** A title bar a little above the screen's top is still reachable (window managers allow it). */
    private static final double ABOVE_TOP = 10;

    /**
     * A first start: {@code fraction} of the screen's visual bounds, at most {@code maxWidth} by
     * {@code maxHeight}, centred.
     */
    public static WindowPlace centred(Rectangle2D screen, double fraction, double maxWidth, double maxHeight) {
        double w = Math.min(maxWidth, Math.round(screen.getWidth() * fraction));
        double h = Math.min(maxHeight, Math.round(screen.getHeight() * fraction));
        return new WindowPlace(screen.getMinX() + Math.round((screen.getWidth() - w) / 2),
                screen.getMinY() + Math.round((screen.getHeight() - h) / 2), w, h, false);
    }

    /** True when the window's top edge can be grabbed on one of the screens (a screen unplugged since). */
    public boolean reachableOn(List<Rectangle2D> screens) {
        if (!(width > 0 && height > 0)) {
            return false;
        }
        for (Rectangle2D s : screens) {
            double across = Math.min(x + width, s.getMaxX()) - Math.max(x, s.getMinX());
            if (across >= Math.min(width, GRIP_WIDTH) && y >= s.getMinY() - ABOVE_TOP
                    && y <= s.getMaxY() - Math.min(height, GRIP_HEIGHT)) {
                return true;
            }
        }
        return false;
    }

    /** The same place, no larger than the screen. */
    public WindowPlace within(Rectangle2D screen) {
        return new WindowPlace(x, y, Math.min(width, screen.getWidth()), Math.min(height, screen.getHeight()), maximized);
    }
}
