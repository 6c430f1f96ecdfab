package touchline.ui;

import javafx.scene.image.ImageView;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;

/**
 * A pane that shows pixels its owner draws itself (premultiplied ARGB), as one image the size of
 * the pane in device pixels: the plot's way around the canvas ({@code views.Raster}).
 */
public final class RasterPane extends DrawnPane {

    private final ImageView view = new ImageView();
    private WritableImage image;
    private long shown;

    public RasterPane(Runnable onResize) {
        super(onResize);
        getChildren().add(view);
    }

    /** Device pixels per logical pixel of the window the pane is in (1 before it is in one). */
    public double scale() {
        return getScene() == null || getScene().getWindow() == null ? 1 : getScene().getWindow().getRenderScaleX();
    }

    /**
     * Shows {@code width} × {@code height} device pixels (row by row, {@code width} a row), drawn at
     * {@code scale} device pixels per logical pixel. FX thread.
     */
    public void show(int[] pixels, int width, int height, double scale) {
        if (image == null || (int) image.getWidth() != width || (int) image.getHeight() != height) {
            image = new WritableImage(width, height);
            view.setImage(image);
        }
        image.getPixelWriter().setPixels(0, 0, width, height, PixelFormat.getIntArgbPreInstance(), pixels, 0, width);
        view.setFitWidth(scale == 1 ? 0 : width / scale);
        view.setFitHeight(scale == 1 ? 0 : height / scale);
        shown++;
    }

    /** How often new pixels were shown (for tests). */
    public long shown() {
        return shown;
    }

    /** The image on screen (for tests), null before the first {@link #show}. */
    public WritableImage image() {
        return image;
    }
}
