package touchline.ui.plots;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.image.Image;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import javafx.scene.paint.Color;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.render.ResizableCanvas;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.io.ByteArrayInputStream;
import java.util.Set;
import touchline.ui.render.ColorClasses;

/**
 * A robot's pre-processed image: GRAY8, RGB888 and colour-class frames are converted pixel by
 * pixel, JPEG and PNG decoded by JavaFX. An image that does not decode (wrong size, corrupt
 * data, unknown format) is drawn as a crossed-out box with the reason; the next good frame
 * shows again.
 */
public final class ImageDataView extends SourcedView {

    static final int MAX_SIDE = 4096;
    private final ResizableCanvas canvas = new ResizableCanvas(() -> dirty = true);
    private Image shown;
    /**
     * The frames shown, one after another, in one image of their size: the window draws it into
     * the texture it has, where a new image for each frame made a new texture (1.2 MB for a
     * 640×480 camera, 12 MB/s at 10 Hz, besides the decoder's own pixels).
     */
    private WritableImage frames;
    private String problem;
    private long decodedVersion = -1;
    private long failures;

    public ImageDataView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.IMAGE_VALUE), source);
        canvas.setId("image-canvas");
        root.setCenter(canvas);
    }

    @Override
    protected String draw(Latest latest) {
        if (latest.version() != decodedVersion) {
            decodedVersion = latest.version();
            problem = null;
            if (latest.data() instanceof Fumanoid.DebugImage img) {
                try {
                    shown = intoFrames(decode(img));
                } catch (IllegalArgumentException e) {
                    shown = null;
                    problem = e.getMessage();
                    failures++;
                }
            } else {
                shown = null;
                // a ROS 2 frame that cannot be shown comes as the reason (model.RosDebugData)
                problem = latest.data() instanceof Fumanoid.DebugText t ? t.getText() : "not an image: " + latest.kind();
                failures++;
            }
        }
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        double w = canvas.getWidth();
        double h = canvas.getHeight();
        g.setFill(Color.gray(0.12));
        g.fillRect(0, 0, w, h);
        if (shown == null) {
            g.setStroke(Color.RED);
            g.setLineWidth(2);
            g.strokeRect(20, 20, w - 40, h - 40);
            g.strokeLine(20, 20, w - 20, h - 20);
            g.strokeLine(w - 20, 20, 20, h - 20);
            g.setFill(Color.WHITE);
            g.fillText("image not shown: " + problem, 30, 40);
            return "image not decoded: " + problem + " (" + failures + " so far)";
        }
        double scale = Math.min(w / shown.getWidth(), h / shown.getHeight());
        g.setImageSmoothing(false);
        g.drawImage(shown, (w - shown.getWidth() * scale) / 2, (h - shown.getHeight() * scale) / 2,
                shown.getWidth() * scale, shown.getHeight() * scale);
        String f = Fumanoid.ImageFormat.forNumber(((Fumanoid.DebugImage) latest.data()).getFormat()) == null ? "?"
                : Fumanoid.ImageFormat.forNumber(((Fumanoid.DebugImage) latest.data()).getFormat()).name();
        return (int) shown.getWidth() + "×" + (int) shown.getHeight() + " " + f
                + (failures > 0 ? " · " + failures + " frames did not decode" : "");
    }

    private Image intoFrames(Image decoded) {
        int w = (int) decoded.getWidth();
        int h = (int) decoded.getHeight();
        if (frames == null || frames.getWidth() != w || frames.getHeight() != h) {
            frames = new WritableImage(w, h);
        }
        frames.getPixelWriter().setPixels(0, 0, w, h, decoded.getPixelReader(), 0, 0);
        return frames;
    }

    /** Converts one image message; throws IllegalArgumentException saying why it cannot. */
    static Image decode(Fumanoid.DebugImage img) {
        byte[] data = img.getData().toByteArray();
        Fumanoid.ImageFormat format = Fumanoid.ImageFormat.forNumber(img.getFormat());
        if (format == null) {
            throw new IllegalArgumentException("unknown image format " + img.getFormat());
        }
        if (format == Fumanoid.ImageFormat.JPEG || format == Fumanoid.ImageFormat.PNG) {
            Image image = new Image(new ByteArrayInputStream(data));
            if (image.isError() || image.getWidth() <= 0) {
                throw new IllegalArgumentException(format + " data (" + data.length + " bytes) does not decode");
            }
            return image;
        }
        int w = img.getWidth();
        int h = img.getHeight();
        if (w <= 0 || h <= 0 || w > MAX_SIDE || h > MAX_SIDE) {
            throw new IllegalArgumentException("bad size " + w + "×" + h);
        }
        int bpp = format == Fumanoid.ImageFormat.RGB888 ? 3 : 1;
        if (data.length < (long) w * h * bpp) {
            throw new IllegalArgumentException(format + " " + w + "×" + h + " needs " + (long) w * h * bpp
                    + " bytes, got " + data.length);
        }
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = switch (format) {
                case GRAY8 -> {
                    int v = data[i] & 0xFF;
                    yield 0xFF000000 | v << 16 | v << 8 | v;
                }
                case RGB888 -> 0xFF000000 | (data[3 * i] & 0xFF) << 16 | (data[3 * i + 1] & 0xFF) << 8 | (data[3 * i + 2] & 0xFF);
                default -> ColorClasses.argb(data[i] & 0xFF);
            };
        }
        WritableImage out = new WritableImage(w, h);
        out.getPixelWriter().setPixels(0, 0, w, h, PixelFormat.getIntArgbInstance(), argb, 0, w);
        return out;
    }
}
