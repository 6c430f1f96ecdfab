package touchline.record;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.atomic.AtomicLong;

/**
 * An {@link EnvelopeSink} that records everything it is given to MCAP. The network thread
 * only puts the envelope in a bounded ring ({@link EnvelopeRing}: never blocks, never
 * allocates; a full ring drops and counts);
 * one writer thread drains it into an {@link EnvelopeWriter} and writes the open chunk at
 * least every {@link #MAX_CHUNK_AGE_NANOS} plus one poll, so a killed process loses at
 * most about a second. Subscribe it to the {@code EnvelopeBus}; close it to finish the file.
 */
public final class Recorder implements EnvelopeSink, AutoCloseable {

    static final long MAX_CHUNK_AGE_NANOS = 800_000_000L;
    private static final long IDLE_PARK_NANOS = 2_000_000L;
    private static final Logger LOG = LoggerFactory.getLogger(Recorder.class);

    // Lock-free hand-off: the network thread does one CAS to enqueue, never takes a lock the
    // writer holds and never wakes it (the writer parks and polls).
    private final EnvelopeRing ring;
    private final EnvelopeWriter writer;
    private final Thread thread;
    private volatile long written;
    private final AtomicLong refused = new AtomicLong();   // not taken: full ring, stopping, failed
    private volatile long discarded;                        // taken but never written (raced with close)
    private volatile boolean stopping;
    private volatile String failure;
    private volatile long bytes;

    public Recorder(Path file, EnvelopeWriter.Options options) throws IOException {
        this(file, options, 1 << 16);
    }

    public Recorder(Path file, EnvelopeWriter.Options options, int queueCapacity) throws IOException {
        this.ring = new EnvelopeRing(queueCapacity);
        this.writer = new EnvelopeWriter(file, options);
        this.thread = new Thread(this::run, "touchline-recorder");
        thread.setDaemon(true);
        thread.start();
    }

    @Override
    public void accept(Envelope envelope) {
        if (failure != null || stopping || !ring.offer(envelope)) {
            refused.incrementAndGet();
        }
    }

    private void run() {
        long count = 0;
        try {
            while (true) {
                // Polling, not a blocking take: a waiting consumer would make every offer() on the
                // network thread signal it (a futex wake per datagram); parked, it costs nothing there.
                long before = count;
                for (Envelope e; count - before < 4096 && (e = ring.poll()) != null; count++) {
                    writer.write(e);
                }
                ring.release();
                if (count > before) {
                    written = count;
                } else if (stopping) {
                    break;
                } else {
                    LockSupport.parkNanos(IDLE_PARK_NANOS);
                }
                writer.flushIfOlderThan(MAX_CHUNK_AGE_NANOS);
                bytes = writer.bytes();
            }
        } catch (IOException | RuntimeException e) {
            written = count;
            failure = "recording stopped: " + e.getMessage();
            LOG.error("{} ({} envelopes written to {})", failure, count, writer.files());
        }
    }

    public RecorderStats stats() {
        long notTaken = refused.get();
        return new RecorderStats(ring.offered() + notTaken, written, notTaken + discarded, bytes, writer.files(),
                failure);
    }

    /** Writes everything queued so far, the summary and the footer; waits for the writer thread. */
    @Override
    public void close() throws IOException {
        stopping = true;
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        // envelopes that raced with stopping were accepted but never written: they count as dropped
        long left = 0;
        for (Envelope e; (e = ring.poll()) != null; ) {
            left++;
        }
        discarded = left;
        writer.close();
        bytes = writer.bytes();
    }
}
