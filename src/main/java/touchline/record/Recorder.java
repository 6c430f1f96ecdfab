package touchline.record;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicLong;

/**
 * An {@link EnvelopeSink} that records everything it is given to MCAP. The publishing
 * thread encodes the envelope into the open chunk itself, while the envelope is still in its
 * cache (handing each envelope to another thread cost that thread more in cache misses than
 * the encoding); whole chunks go to a {@link BackgroundFiles} thread, so no publisher ever
 * waits for the disk. When the disk falls behind by more than {@link #MAX_PENDING_BYTES},
 * envelopes are refused and counted as dropped, so the file stays consistent. The open chunk
 * is written at least every {@link #MAX_CHUNK_AGE_NANOS} plus one tick, so a killed process
 * loses at most about a second. Start it ({@link #start()}: the disk thread), subscribe it to
 * the {@code EnvelopeBus}; close it to finish the file.
 */
public final class Recorder implements EnvelopeSink, AutoCloseable {

    static final long MAX_CHUNK_AGE_NANOS = 800_000_000L;
    static final long MAX_PENDING_BYTES = 64L << 20;
    private static final Logger LOG = LoggerFactory.getLogger(Recorder.class);

    private final BackgroundFiles disk;
    private final long maxPendingBytes;
    private final EnvelopeWriter writer;   // guarded by itself: publishers and the disk thread's tick
    private final AtomicLong refused = new AtomicLong();
    private long written;                  // guarded by writer
    private volatile long writtenSoFar;
    private volatile boolean stopping;
    private volatile String failure;
    private volatile long bytes;

    public Recorder(Path file, EnvelopeWriter.Options options) throws IOException {
        this(file, options, MAX_PENDING_BYTES);
    }

    /** @param maxPendingBytes how far the disk may fall behind before envelopes are refused */
    Recorder(Path file, EnvelopeWriter.Options options, long maxPendingBytes) throws IOException {
        this.maxPendingBytes = maxPendingBytes;
        this.disk = new BackgroundFiles("touchline-recorder", this::tick);
        EnvelopeWriter w;
        try {
            w = new EnvelopeWriter(file, options, disk::open);
        } catch (IOException | RuntimeException e) {
            disk.close();
            throw e;
        }
        this.writer = w;
    }

    /** Starts the disk thread (its owner does, once it has made the recorder); returns this. */
    public Recorder start() {
        disk.start();
        return this;
    }

    /** Test hook: the disk thread writes nothing until {@code release} opens. */
    void holdDisk(java.util.concurrent.CountDownLatch release) {
        disk.hold(release);
    }

    @Override
    public void accept(Envelope envelope) {
        if (failure != null || stopping || disk.pendingBytes() > maxPendingBytes) {
            refused.incrementAndGet();
            return;
        }
        synchronized (writer) {
            if (stopping) {
                refused.incrementAndGet();
                return;
            }
            try {
                writer.write(envelope);
                writtenSoFar = ++written;
            } catch (IOException | RuntimeException e) {
                refused.incrementAndGet();
                fail(e);
            }
        }
    }

    /** On the disk thread: writes an old open chunk, refreshes the byte count, picks up disk errors. */
    private void tick() {
        if (writer == null) {
            // only when the constructor failed: its close drains what the writer had queued
            return;
        }
        synchronized (writer) {
            if (stopping) {
                return;
            }
            try {
                writer.flushIfOlderThan(MAX_CHUNK_AGE_NANOS);
                bytes = writer.bytes();
            } catch (IOException | RuntimeException e) {
                fail(e);
            }
        }
        if (failure == null && disk.failure() != null) {
            failure = disk.failure();
            LOG.error("{} ({} envelopes written to {})", failure, writtenSoFar, writer.files());
        }
    }

    private void fail(Exception e) {
        if (failure == null) {
            failure = "recording stopped: " + e.getMessage();
            LOG.error("{} ({} envelopes written to {})", failure, written, writer.files());
        }
    }

    public RecorderStats stats() {
        long notTaken = refused.get();
        long done = writtenSoFar;
        return new RecorderStats(done + notTaken, done, notTaken, bytes, writer.files(), failure);
    }

    /** Writes the last chunk, the summary and the footer, and waits until the disk has it all. */
    @Override
    public void close() throws IOException {
        IOException closing = null;
        synchronized (writer) {
            if (stopping) {
                return;
            }
            stopping = true;
            try {
                writer.close();
                bytes = writer.bytes();
            } catch (IOException e) {
                closing = e;
            }
        }
        disk.close();
        if (failure == null && disk.failure() != null) {
            failure = disk.failure();
        }
        if (closing != null) {
            throw closing;
        }
    }
}
