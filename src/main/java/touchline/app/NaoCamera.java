package touchline.app;

import touchline.transport.EnvelopeSink;
import touchline.transport.nao.CameraSettings;
import touchline.transport.nao.NaoCameraStream;
import touchline.transport.nao.NaoClientKeys;
import touchline.transport.nao.NaoEnvelopeChannel;

/**
 * One NAO camera server opened through the application core ({@link NaoSession#camera()},
 * or {@link Naos#connectCamera} for the camera alone): it fetches frames only while
 * {@link #watch watched}, and every frame enters the console's Envelope stream, where the
 * faces read it ({@link Naos#camera()}) — the same way as frames that come from a remote
 * Touchline or a replay. Fetching frames sends the robot no command: it is not held by match
 * mode. The faces never hold the camera stream itself.
 */
public final class NaoCamera implements AutoCloseable {

    private final NaoCameraStream stream;
    private final java.util.function.Consumer<NaoCamera> onClose;
    private AutoCloseable watching; // guarded by this

    /** Publishing into a NAO session's pipeline (the session closes it). */
    NaoCamera(String host, int port, NaoEnvelopeChannel channel, NaoClientKeys keys,
              touchline.transport.MicrosClock wall, touchline.transport.MonotonicClock monotonic) {
        this.stream = new NaoCameraStream(host, port, channel, keys, wall, monotonic);
        this.onClose = camera -> { };
    }

    /**
     * The camera alone, publishing into its own pipeline ending in {@code sink}.
     *
     * @param onClose told when it closes (the console forgets it)
     */
    NaoCamera(String host, int port, EnvelopeSink sink, NaoClientKeys keys, touchline.transport.MicrosClock wall,
              touchline.transport.MonotonicClock monotonic, java.util.function.Consumer<NaoCamera> onClose) {
        this.stream = new NaoCameraStream(host, port, sink, keys, wall, monotonic);
        this.onClose = onClose;
    }

    /** Starts the camera's thread (the console does, once it has made it). */
    NaoCamera start() {
        stream.start();
        return this;
    }

    /** Starts ({@code true}) or stops fetching frames. */
    public synchronized void watch(boolean on) {
        if (on && watching == null) {
            watching = stream.subscribe();
        } else if (!on && watching != null) {
            try {
                watching.close();
            } catch (Exception impossible) {
                throw new IllegalStateException(impossible); // a subscription's close does not throw
            }
            watching = null;
        }
    }

    public synchronized boolean watching() {
        return watching != null;
    }

    /** Resolution, colour space and rate; the server is configured again before the next frame. */
    public void configure(CameraSettings settings) {
        stream.configure(settings);
    }

    public CameraSettings settings() {
        return stream.settings();
    }

    /** Why no frames come (no reply, the server's error, a key it refused), or "" while they flow. */
    public String problem() {
        String error = stream.lastError();
        return error == null ? "" : error;
    }

    /** Stops fetching and returns at once; {@link #stopped()} completes when the camera's thread has ended. */
    @Override
    public void close() {
        watch(false);
        stream.close();
        onClose.accept(this);
    }

    java.util.concurrent.CompletionStage<Void> stopped() {
        return stream.stopped();
    }
}
