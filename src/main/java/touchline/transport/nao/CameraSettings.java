package touchline.transport.nao;

import touchline.protocol.nao.CameraFormat;

/**
 * What a NAO camera server is asked to deliver: resolution id (0 QQVGA .. 3 4VGA), colour
 * space id (NAOqi's, e.g. 11 kRGB) and frames per second (1..30). The constructor rejects
 * values the camera server does not know, with a message naming the allowed ones.
 */
public record CameraSettings(int resolution, int colorSpace, int fps) {

    public static final CameraSettings DEFAULT = new CameraSettings(2, 11, 15);

    public CameraSettings {
        if (!CameraFormat.isKnownResolution(resolution)) {
            throw new IllegalArgumentException("unknown resolution " + resolution
                    + " (0 = 160x120, 1 = 320x240, 2 = 640x480, 3 = 1280x960)");
        }
        if (!CameraFormat.isKnownColorSpace(colorSpace)) {
            throw new IllegalArgumentException("unknown colour space " + colorSpace
                    + " (0 kYuv, 9 kYUV422, 10 kYUV, 11 kRGB, 12 kHSY, 13 kBGR)");
        }
        if (fps < 1 || fps > 30) {
            throw new IllegalArgumentException("fps must be 1..30, was " + fps);
        }
    }
}
