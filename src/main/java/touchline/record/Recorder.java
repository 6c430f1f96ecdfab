package touchline.record;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.atomic.AtomicLong;

/**
 * An {@link EnvelopeSink} that records everything it is given to MCAP. The network thread
 * only puts the envelope in a bounded queue (never blocks; a full queue drops and counts);
 * one writer thread drains it into an {@link EnvelopeWriter} and writes the open chunk at
 * least every {@link #MAX_CHUNK_AGE_NANOS} plus one poll, so a killed process loses at
 * most about a second. Subscribe it to the {@code EnvelopeBus}; close it to finish the file.
 */
public final class Recorder implements EnvelopeSink, AutoCloseable {

    static final long MAX_CHUNK_AGE_NANOS = 800_000_000L;
    private static final long IDLE_PARK_NANOS = 2_000_000L;
    private static final Logger LOG = LoggerFactory.getLogger(Recorder.class);

    // Lock-free hand-off: the network thread does one CAS to count and one to enqueue, never
    // takes a lock the writer holds and never wakes it (the writer parks and polls).
    private final ConcurrentLinkedQueue<Envelope> queue = new ConcurrentLinkedQueue<>();
    private final AtomicInteger queued = new AtomicInteger();
    private final int capacity;
    private final EnvelopeWriter writer;
    private final Thread thread;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong written = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private volatile boolean stopping;
    private volatile String failure;
    private volatile long bytes;

    public Recorder(Path file, EnvelopeWriter.Options options) throws IOException {
        this(file, options, 1 << 16);
    }

    public Recorder(Path file, EnvelopeWriter.Options options, int queueCapacity) throws IOException {
        this.capacity = queueCapacity;
        this.writer = new EnvelopeWriter(file, options);
        this.thread = new Thread(this::run, "touchline-recorder");
        thread.setDaemon(true);
        thread.start();
    }

    @Override
    public void accept(Envelope envelope) {
        received.incrementAndGet();
        if (failure != null || stopping || queued.get() >= capacity) {
            dropped.incrementAndGet();
            return;
        }
        queued.incrementAndGet();
        queue.offer(envelope);
    }

    private void run() {
        List<Envelope> batch = new ArrayList<>(4096);
        try {
            while (true) {
                // Polling, not a blocking take: a waiting consumer would make every offer() on the
                // network thread signal it (a futex wake per datagram); parked, it costs nothing there.
                for (Envelope e; batch.size() < 4096 && (e = queue.poll()) != null; ) {
                    batch.add(e);
                }
                queued.addAndGet(-batch.size());
                if (!batch.isEmpty()) {
                    for (Envelope e : batch) {
                        writer.write(e);
                    }
                    written.addAndGet(batch.size());
                    batch.clear();
                } else if (stopping) {
                    break;
                } else {
                    LockSupport.parkNanos(IDLE_PARK_NANOS);
                }
                writer.flushIfOlderThan(MAX_CHUNK_AGE_NANOS);
                bytes = writer.bytes();
            }
        } catch (IOException | RuntimeException e) {
            failure = "recording stopped: " + e.getMessage();
            LOG.error("{} ({} envelopes written to {})", failure, written.get(), writer.files());
        }
    }

    public RecorderStats stats() {
        return new RecorderStats(received.get(), written.get(), dropped.get(), bytes, writer.files(), failure);
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
        for (Envelope e; (e = queue.poll()) != null; ) {
            dropped.incrementAndGet();
        }
        writer.close();
        bytes = writer.bytes();
    }
}
