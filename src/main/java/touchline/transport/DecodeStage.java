package touchline.transport;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * The second thread of a console with a team key: the event loop checks each datagram's tag
 * (in arrival order, dropping forgeries) and hands what passed here, where it is decoded and
 * published, so that on two cores the HMAC runs beside the decode instead of before it
 * (docs/benchmarks.md, issue 15). One thread and one FIFO queue: the order of the envelopes is
 * the order of the datagrams. Handed over in batches (one per socket read), so the wake-up
 * costs once per batch, not per datagram. Bounded: when {@link #CAPACITY} batches wait, the
 * event loop waits too and the datagrams stay in the socket's receive buffer.
 */
final class DecodeStage implements AutoCloseable {

    static final int CAPACITY = 256;
    private static final int MAX_BATCH = 64;
    private static final List<Supplier<Envelope>> STOP = List.of();

    private final BlockingQueue<List<Supplier<Envelope>>> queue = new ArrayBlockingQueue<>(CAPACITY);
    private final EnvelopeSink sink;
    private final Thread thread;
    private List<Supplier<Envelope>> batch = new ArrayList<>(MAX_BATCH);
    private volatile boolean closed;

    DecodeStage(EnvelopeSink sink) {
        this.sink = sink;
        this.thread = new Thread(this::run, "touchline-decode");
        thread.setDaemon(true);
        thread.start();
    }

    /** Event loop: one datagram's remaining work (decode, envelope), published in order. */
    void add(Supplier<Envelope> work) {
        batch.add(work);
        if (batch.size() >= MAX_BATCH) {
            flush();
        }
    }

    /** Event loop: hands the batch over (at the end of each socket read). */
    void flush() {
        if (batch.isEmpty()) {
            return;
        }
        List<Supplier<Envelope>> full = batch;
        batch = new ArrayList<>(MAX_BATCH);
        try {
            while (!queue.offer(full, 100, TimeUnit.MILLISECONDS)) {
                if (closed) {
                    return;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void run() {
        while (true) {
            List<Supplier<Envelope>> work;
            try {
                work = queue.take();
            } catch (InterruptedException e) {
                return;
            }
            if (work == STOP) {
                return;
            }
            for (Supplier<Envelope> w : work) {
                try {
                    sink.accept(w.get());
                } catch (RuntimeException e) {
                    // as on the event loop: this datagram is lost, the next one is not
                    org.slf4j.LoggerFactory.getLogger(DecodeStage.class).warn("inbound decode: {}", e.toString());
                }
            }
        }
    }

    /** After the channel is closed: publishes what waits, then stops the thread. */
    @Override
    public void close() {
        closed = true;
        try {
            if (queue.offer(STOP, 2, TimeUnit.SECONDS)) {
                thread.join(2000);
            } else {
                thread.interrupt();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
