package touchline.ui.render;

import javafx.scene.SnapshotParameters;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import javafx.scene.paint.Color;
import javafx.scene.text.Font;
import javafx.scene.text.Text;
import javafx.scene.transform.Transform;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The labels of a view drawn into a {@link Raster} (the plot's axes and legend, the region
 * overlay's legend) as small pictures ({@link Raster.Sprite}), each rendered once by JavaFX (a
 * {@link Text} snapshot: the same font and anti-aliasing as any label of the window) and kept for
 * the next frames: they are a few dozen strings ("-1", "0", "15 s", the series' names) that come
 * back frame after frame, so text costs nothing once they are known. The {@link #KEPT} used most
 * recently are kept. FX thread.
 */
public final class LabelSprites {

    static final int KEPT = 128;

    private record Key(String text, int argb, double scale) { }

    private final Text text = new Text();
    private final Map<Key, Raster.Sprite> kept = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Key, Raster.Sprite> eldest) {
            return size() > KEPT;
        }
    };

    public LabelSprites(Font font) {
        text.setFont(font);
    }

    /** The label {@code s} in {@code colour} at {@code scale} device pixels per logical pixel. */
    public Raster.Sprite of(String s, Color colour, double scale) {
        return kept.computeIfAbsent(new Key(s, Raster.opaque(colour), scale), k -> render(s, colour, scale));
    }

    private Raster.Sprite render(String s, Color colour, double scale) {
        text.setText(s);
        text.setFill(colour);
        SnapshotParameters p = new SnapshotParameters();
        p.setFill(Color.TRANSPARENT);
        if (scale != 1) {
            p.setTransform(Transform.scale(scale, scale));
        }
        WritableImage image = text.snapshot(p, null);
        int w = (int) image.getWidth();
        int h = (int) image.getHeight();
        int[] pixels = new int[w * h];
        image.getPixelReader().getPixels(0, 0, w, h, PixelFormat.getIntArgbPreInstance(), pixels, 0, w);
        return new Raster.Sprite(w, h, pixels);
    }
}
