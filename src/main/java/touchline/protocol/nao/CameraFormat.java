package touchline.protocol.nao;

/**
 * NAOqi camera resolution ids (alvisiondefinitions.h) and their frame sizes, plus the colour
 * space ids the camera server accepts. Used to label frames and to compute raw sizes for the
 * compression ratio.
 */
public final class CameraFormat {

    private static final int[][] SIZES = {{160, 120}, {320, 240}, {640, 480}, {1280, 960}};
    private static final int[] COLOR_SPACES = {0, 9, 10, 11, 12, 13};

    private CameraFormat() {
    }

    public static boolean isKnownResolution(int id) {
        return id >= 0 && id < SIZES.length;
    }

    public static boolean isKnownColorSpace(int id) {
        for (int c : COLOR_SPACES) {
            if (c == id) {
                return true;
            }
        }
        return false;
    }

    public static int width(int resolution) {
        return isKnownResolution(resolution) ? SIZES[resolution][0] : 0;
    }

    public static int height(int resolution) {
        return isKnownResolution(resolution) ? SIZES[resolution][1] : 0;
    }

    /** Bytes of one uncompressed RGB frame, the baseline JPEG compression is measured against. */
    public static long rawRgbBytes(int resolution) {
        return 3L * width(resolution) * height(resolution);
    }
}
