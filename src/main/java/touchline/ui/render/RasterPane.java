package touchline.ui.render;

import javafx.scene.image.ImageView;
import javafx.scene.image.PixelBuffer;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;

import java.nio.IntBuffer;

/**
 * A pane that shows pixels its owner draws itself (premultiplied ARGB), as one image the size of
 * the pane in device pixels: the way around the canvas for the plot and the region overlay
 * ({@code views.Raster}). Two buffers: the owner draws into the one not on screen
 * ({@link #back}) and {@link #showBack} puts it on screen, so JavaFX reads the pixels where they
 * were drawn (no copy on the FX thread) and never while they are drawn (the render thread may
 * still be drawing the last frame while the next one is made).
 */
public final class RasterPane extends DrawnPane {

    private final ImageView view = new ImageView();
    private final int[][] buffers = new int[2][];
    @SuppressWarnings("unchecked")
    private final PixelBuffer<IntBuffer>[] pixelBuffers = new PixelBuffer[2];
    private final WritableImage[] images = new WritableImage[2];
    private int back;
    private int width;
    private int height;

    public RasterPane(Runnable onResize) {
        super(onResize);
        getChildren().add(view);
    }

    /** Device pixels per logical pixel of the window the pane is in (1 before it is in one). */
    public double scale() {
        return getScene() == null || getScene().getWindow() == null ? 1 : getScene().getWindow().getRenderScaleX();
    }

    /**
     * The pixels not on screen, {@code width} × {@code height} device pixels row by row, to draw the
     * next picture into (new ones, blank, when the size changed). FX thread.
     */
    public int[] back(int width, int height) {
        if (width != this.width || height != this.height) {
            this.width = width;
            this.height = height;
            for (int i = 0; i < 2; i++) {
                buffers[i] = new int[width * height];
                pixelBuffers[i] = new PixelBuffer<>(width, height, IntBuffer.wrap(buffers[i]), PixelFormat.getIntArgbPreInstance());
                images[i] = new WritableImage(pixelBuffers[i]);
            }
        }
        return buffers[back];
    }

    /** Puts the pixels drawn into {@link #back} on screen, drawn at {@code scale} device pixels per logical pixel. FX thread. */
    public void showBack(double scale) {
        pixelBuffers[back].updateBuffer(b -> null); // all of it changed
        view.setImage(images[back]);
        view.setFitWidth(scale == 1 ? 0 : width / scale);
        view.setFitHeight(scale == 1 ? 0 : height / scale);
        back ^= 1;
    }
}
