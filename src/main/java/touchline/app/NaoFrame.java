package touchline.app;

/**
 * One NAO camera frame as the console's Envelope stream carried it (live, from a remote
 * Touchline, or replayed): what a face draws or saves.
 *
 * @param jpeg       the JPEG bytes (do not modify; shared by every reader)
 * @param width      pixels, from the JPEG header (0 if unreadable)
 * @param height     pixels, from the JPEG header (0 if unreadable)
 * @param sequence   1 for the first frame the console saw, +1 per frame, live and replayed alike (a redraw key)
 * @param timeMicros the frame envelope's time (its receive time where it was fetched)
 * @param source     the camera server's address as the envelope names it
 */
public record NaoFrame(byte[] jpeg, int width, int height, long sequence, long timeMicros, String source) {
}
