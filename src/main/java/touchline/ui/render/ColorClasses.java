package touchline.ui.render;

import javafx.scene.paint.Color;

/**
 * The HaViMo2 colour classes as the camera reports them (a number per pixel, cell or
 * region) and the colour each is drawn in; unknown numbers draw grey and are named so.
 */
public final class ColorClasses {

    private static final String[] NAMES = {"unclassified", "ball", "field", "goal yellow", "goal blue", "white",
            "team cyan", "team magenta"};
    private static final Color[] COLORS = {Color.gray(0.25), Color.ORANGE, Color.FORESTGREEN, Color.GOLD,
            Color.DODGERBLUE, Color.WHITE, Color.CYAN, Color.MAGENTA};

    private ColorClasses() { }

    public static int count() {
        return NAMES.length;
    }

    public static Color color(int c) {
        return c >= 0 && c < COLORS.length ? COLORS[c] : Color.GRAY;
    }

    public static String name(int c) {
        return c >= 0 && c < NAMES.length ? NAMES[c] : "class " + c;
    }

    public static int argb(int c) {
        Color k = color(c);
        return 0xFF000000 | (int) (k.getRed() * 255) << 16 | (int) (k.getGreen() * 255) << 8 | (int) (k.getBlue() * 255);
    }
}
