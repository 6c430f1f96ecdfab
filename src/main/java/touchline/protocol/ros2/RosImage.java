package touchline.protocol.ros2;

import java.util.Locale;

/**
 * A ROS 2 camera frame as pixels a view can show: {@code sensor_msgs/msg/Image} in rgb8, bgr8,
 * rgba8, bgra8, mono8 and yuv422 (UYVY, ROS's {@code yuv422}) or yuyv ({@code yuv422_yuy2},
 * {@code yuyv}) becomes RGB or grey bytes, row padding ({@code step}) dropped;
 * {@code sensor_msgs/msg/CompressedImage} (jpeg, png) stays compressed for the view's decoder.
 * Pure: one decoded message in, a {@link Frame} out; an image it cannot show is a
 * {@link Refused} saying why, never an exception.
 */
public final class RosImage {

    /** The largest side accepted: a bigger frame is refused rather than allocated. */
    public static final int MAX_SIDE = 4096;

    /** What one message gives. */
    public sealed interface Frame permits Pixels, Compressed, Refused { }

    /** {@code width × height} pixels, 3 bytes RGB each or ({@code grey}) one byte each, rows packed. */
    public record Pixels(int width, int height, boolean grey, byte[] data) implements Frame { }

    /** A JPEG or ({@code png}) PNG file's bytes. */
    public record Compressed(boolean png, byte[] data) implements Frame { }

    /** Why the message shows no picture. */
    public record Refused(String reason) implements Frame { }

    /** Whether {@code typeName} is one of the two image types. */
    public static boolean isImage(String typeName) {
        return typeName.equals("sensor_msgs/msg/Image") || typeName.equals("sensor_msgs/msg/CompressedImage");
    }

    /** The frame {@code m} holds (an Image or a CompressedImage). */
    public Frame frame(RosMessage m) {
        if (!(m.get("data") instanceof byte[] data)) {
            return new Refused(m.typeName() + " without byte data");
        }
        if (m.typeName().equals("sensor_msgs/msg/CompressedImage")) {
            return compressed(String.valueOf(m.get("format")), data);
        }
        return raw(String.valueOf(m.get("encoding")), (int) m.number("width"), (int) m.number("height"),
                (long) m.number("step"), data);
    }

    private static Frame compressed(String format, byte[] data) {
        String f = format.toLowerCase(Locale.ROOT);
        boolean pngMagic = data.length >= 4 && (data[0] & 0xFF) == 0x89 && data[1] == 'P' && data[2] == 'N' && data[3] == 'G';
        boolean jpegMagic = data.length >= 2 && (data[0] & 0xFF) == 0xFF && (data[1] & 0xFF) == 0xD8;
        if (f.contains("png") || pngMagic) {
            return new Compressed(true, data);
        }
        if (f.contains("jpeg") || f.contains("jpg") || jpegMagic) {
            return new Compressed(false, data);
        }
        return new Refused("compressed format '" + format + "' is neither jpeg nor png");
    }

    private static Frame raw(String encoding, int w, int h, long step, byte[] data) {
        if (w <= 0 || h <= 0 || w > MAX_SIDE || h > MAX_SIDE) {
            return new Refused("bad size " + w + "×" + h);
        }
        String e = encoding.toLowerCase(Locale.ROOT);
        int bytesPerPixel = switch (e) {
            case "mono8", "8uc1" -> 1;
            case "yuv422", "uyvy", "yuv422_yuy2", "yuyv" -> 2;
            case "rgb8", "bgr8", "8uc3" -> 3;
            case "rgba8", "bgra8", "8uc4" -> 4;
            default -> 0;
        };
        if (bytesPerPixel == 0) {
            return new Refused("encoding '" + encoding + "' not shown (rgb8, bgr8, rgba8, bgra8, mono8, yuv422, yuyv are)");
        }
        long row = step <= 0 ? (long) w * bytesPerPixel : step;
        if (row < (long) w * bytesPerPixel || (bytesPerPixel == 2 && w % 2 != 0)) {
            return new Refused(encoding + " " + w + "×" + h + ": step " + step + " too short for its width");
        }
        if (data.length < row * (h - 1) + (long) w * bytesPerPixel) {
            return new Refused(encoding + " " + w + "×" + h + " needs " + row * h + " bytes, got " + data.length);
        }
        if (bytesPerPixel == 1) {
            byte[] grey = new byte[w * h];
            for (int y = 0; y < h; y++) {
                System.arraycopy(data, (int) (y * row), grey, y * w, w);
            }
            return new Pixels(w, h, true, grey);
        }
        byte[] rgb = new byte[w * h * 3];
        for (int y = 0; y < h; y++) {
            int in = (int) (y * row);
            int out = y * w * 3;
            if (bytesPerPixel == 2) {
                yuv(e.equals("yuv422") || e.equals("uyvy"), data, in, rgb, out, w);
                continue;
            }
            boolean bgr = e.startsWith("bgr");
            for (int x = 0; x < w; x++, in += bytesPerPixel, out += 3) {
                rgb[out] = data[bgr ? in + 2 : in];
                rgb[out + 1] = data[in + 1];
                rgb[out + 2] = data[bgr ? in : in + 2];
            }
        }
        return new Pixels(w, h, false, rgb);
    }

    /** One row of 4:2:2 (two pixels share U and V) to RGB by ITU-R BT.601. */
    private static void yuv(boolean uyvy, byte[] d, int in, byte[] rgb, int out, int w) {
        for (int x = 0; x < w; x += 2, in += 4) {
            int y0 = d[uyvy ? in + 1 : in] & 0xFF;
            int y1 = d[uyvy ? in + 3 : in + 2] & 0xFF;
            int u = (d[uyvy ? in : in + 1] & 0xFF) - 128;
            int v = (d[uyvy ? in + 2 : in + 3] & 0xFF) - 128;
            out = pixel(y0, u, v, rgb, out);
            out = pixel(y1, u, v, rgb, out);
        }
    }

    private static int pixel(int y, int u, int v, byte[] rgb, int out) {
        rgb[out] = clamp(y + 1.402 * v);
        rgb[out + 1] = clamp(y - 0.344136 * u - 0.714136 * v);
        rgb[out + 2] = clamp(y + 1.772 * u);
        return out + 3;
    }

    private static byte clamp(double v) {
        return (byte) Math.max(0, Math.min(255, (int) Math.round(v)));
    }
}
