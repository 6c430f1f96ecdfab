package touchline.transport.nao;

/**
 * One JPEG frame from a NAO camera server as the console received it.
 *
 * @param jpeg              the JPEG bytes (do not modify; shared by all viewers)
 * @param width             pixels, from the JPEG header (0 if unreadable)
 * @param height            pixels, from the JPEG header (0 if unreadable)
 * @param sequence          1 for the first frame of a stream, +1 per frame
 * @param receiveTimeMicros when it arrived, microseconds since the epoch
 * @param settings          the camera settings in force when it was fetched
 */
public record CameraFrame(byte[] jpeg, int width, int height, long sequence, long receiveTimeMicros,
                          CameraSettings settings) {
}
