package touchline.app;

import touchline.record.EnvelopeWriter;
import touchline.record.Recorder;
import touchline.record.RecorderStats;
import touchline.transport.LiveStream;
import touchline.transport.remote.BridgedSchema;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Recording the console's stream to MCAP: one recording at a time (the window's record panel,
 * {@code touchline record}, {@code serve --record}); the file is finished (footer and index) when
 * it stops, and on the way out within a bound ({@link #finish}).
 */
public final class Recordings {

    private final LiveStream bus;
    private final BridgedSchema.Source bridged;
    private volatile Recorder recorder;    // written under this; read without it (current())
    private AutoCloseable subscription;

    /** @param bridged a bridged robot's channel's own encoding and schema, which its recorded channel keeps */
    Recordings(LiveStream bus, BridgedSchema.Source bridged) {
        this.bus = bus;
        this.bridged = bridged;
    }

    /** Starts recording every envelope (in and out, live or replayed) into an MCAP file. */
    public Recorder start(Path file) throws IOException {
        return start(file, EnvelopeWriter.Options.defaults());
    }

    /**
     * As {@link #start(Path)}, with the writer's options (split, compression, camera rate, team files);
     * a bridged robot's channels keep their own encoding and schema (ros2msg/cdr, json, protobuf).
     */
    public synchronized Recorder start(Path file, EnvelopeWriter.Options options) throws IOException {
        stop();
        recorder = new Recorder(file, options.withBridgedSchemas(bridged)).start();
        subscription = bus.subscribe(recorder);
        return recorder;
    }

    /** Stops and closes the recording; the file is complete (footer and index) afterwards. */
    public synchronized void stop() throws IOException {
        if (recorder != null) {
            try {
                subscription.close();
            } catch (Exception ignored) {
                // unsubscribing cannot fail
            }
            recorder.close();
            recorder = null;
        }
    }

    /**
     * Ends the recording, as {@link #stop()}, waiting at most {@code timeoutMillis} for the file to
     * be finished: what a face calls on its way out (the window closing, a signal), where the
     * process must not hang on a stuck disk. True when the file is finished (or nothing was recording).
     */
    public boolean finish(long timeoutMillis) {
        Thread finishing = new Thread(() -> {
            try {
                stop();
            } catch (IOException e) {
                org.slf4j.LoggerFactory.getLogger(Recordings.class).warn("finishing the recording: {}", e.toString());
            }
        }, "touchline-finish-recording");
        finishing.start();
        try {
            finishing.join(timeoutMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return !finishing.isAlive();
    }

    /**
     * As {@link #finish}, without waiting: the file is finished on a thread of its own, which then
     * tells {@code done} whether it was finished within the bound (what the window's close does,
     * off the JavaFX thread).
     */
    public void finishThen(long timeoutMillis, java.util.function.Consumer<Boolean> done) {
        new Thread(() -> done.accept(finish(timeoutMillis)), "touchline-finish-recording-wait").start();
    }

    /**
     * The running recording's figures, if one runs (until its file is finished). Does not wait
     * for a recording being finished, so a frame may ask.
     */
    public Optional<RecorderStats> current() {
        Recorder r = recorder;
        return r == null ? Optional.empty() : Optional.of(r.stats());
    }

    void close() {
        try {
            stop();
        } catch (IOException e) {
            org.slf4j.LoggerFactory.getLogger(Recordings.class).warn("closing the recording: {}", e.toString());
        }
    }
}
