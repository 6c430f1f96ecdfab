package touchline.serve;

import touchline.transport.Envelope;

import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The standard channels' conversion off the publishing thread: the thread that ingests the
 * field's datagrams only checks whether an envelope is wanted ({@link StandardChannels#wanted})
 * and queues it; one converter thread, in order, turns it into the Foxglove messages and
 * queues those for the viewers. The queue is bounded: when the converter falls behind, what
 * does not fit is counted as dropped, and ingest never waits.
 */
final class StandardConversion implements AutoCloseable {

    static final int QUEUE = 8192;

    private final StandardChannels standard;
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong failed = new AtomicLong();
    private final ThreadPoolExecutor thread;

    StandardConversion(StandardChannels standard) {
        this.standard = standard;
        this.thread = new ThreadPoolExecutor(1, 1, 0, TimeUnit.SECONDS, new ArrayBlockingQueue<>(QUEUE), r -> {
            Thread t = new Thread(r, "touchline-serve-standard");
            t.setDaemon(true);
            return t;
        }, (r, executor) -> dropped.incrementAndGet());
    }

    /**
     * Starts the conversion's thread, from the server's {@code start()}: here, not at the first
     * offer, since a thread started from touchline-decode would inherit the CPU that thread is
     * kept on (transport.CoreSplit).
     */
    void start() {
        thread.prestartCoreThread();
    }

    /** From the publishing thread: converts {@code e} later when a viewer may want it. Never blocks. */
    void offer(Envelope e) {
        if (!standard.wanted(e)) {
            return;
        }
        try {
            thread.execute(() -> convert(e));
        } catch (RejectedExecutionException ignored) {
            dropped.incrementAndGet(); // closing
        }
    }

    private void convert(Envelope e) {
        try {
            standard.accept(e);
        } catch (RuntimeException ex) { // a message the converters do not expect: counted, the others go on
            if (failed.getAndIncrement() == 0) {
                org.slf4j.LoggerFactory.getLogger(StandardConversion.class).warn("converting {} of robot {} to a "
                        + "standard message failed: {}", e.kind(), e.robotId(), ex.toString());
            }
        }
    }

    /** Envelopes not converted because the converter was behind (or closing). */
    long dropped() {
        return dropped.get();
    }

    @Override
    public void close() {
        thread.shutdownNow();
    }
}
