package touchline.protocol.nao;

/**
 * Reads the frame size from a JPEG's start-of-frame marker, so a camera frame is labelled
 * with what the server actually encoded rather than what the console asked for.
 */
public final class JpegHeader {

    private JpegHeader() {
    }

    /** {width, height}, or null when the bytes are not a JPEG with a readable SOF marker. */
    public static int[] size(byte[] jpeg) {
        if (jpeg == null || jpeg.length < 4 || (jpeg[0] & 0xFF) != 0xFF || (jpeg[1] & 0xFF) != 0xD8) {
            return null;
        }
        int i = 2;
        while (i + 4 <= jpeg.length) {
            if ((jpeg[i] & 0xFF) != 0xFF) {
                return null;
            }
            int marker = jpeg[i + 1] & 0xFF;
            if (marker == 0xFF) {
                i++; // fill byte
                continue;
            }
            int length = ((jpeg[i + 2] & 0xFF) << 8) | (jpeg[i + 3] & 0xFF);
            boolean startOfFrame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
            if (startOfFrame) {
                if (i + 9 > jpeg.length) {
                    return null;
                }
                int height = ((jpeg[i + 5] & 0xFF) << 8) | (jpeg[i + 6] & 0xFF);
                int width = ((jpeg[i + 7] & 0xFF) << 8) | (jpeg[i + 8] & 0xFF);
                return new int[] {width, height};
            }
            if (marker == 0xD9 || marker == 0xDA || length < 2) {
                return null; // end of image or scan data before any SOF
            }
            i += 2 + length;
        }
        return null;
    }
}
