package touchline.record.foxglove;

import com.google.protobuf.ByteString;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A plain dark PNG of a given size: what HaViMo2 region rectangles are drawn on when the robot
 * sends only the rectangles, since an Image panel shows annotations only over an image. A few
 * hundred bytes, made once per size (bounded: robots send a handful of frame sizes). Thread-safe.
 */
final class Canvas {

    private static final int MAX_SIDE = 4096;
    private static final int MAX_SIZES = 16;
    private final Map<Long, ByteString> bySize = new LinkedHashMap<>();

    /** The PNG, or null when the size is not a sensible frame ({@code 1..4096} per side). */
    synchronized ByteString png(int width, int height) {
        if (width < 1 || height < 1 || width > MAX_SIDE || height > MAX_SIDE) {
            return null;
        }
        long key = ((long) width << 32) | height;
        ByteString png = bySize.get(key);
        if (png == null) {
            png = ByteString.copyFrom(encode(width, height)); // immutable: shared by every message of this size
            if (bySize.size() >= MAX_SIZES) {
                bySize.remove(bySize.keySet().iterator().next());
            }
            bySize.put(key, png);
        }
        return png;
    }

    private static byte[] encode(int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_BYTE_GRAY);
        java.awt.Graphics2D g = image.createGraphics();
        g.setColor(new java.awt.Color(32, 32, 32));
        g.fillRect(0, 0, width, height);
        g.dispose();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", out);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a memory stream does not fail
        }
        return out.toByteArray();
    }
}
