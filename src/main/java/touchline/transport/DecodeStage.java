package touchline.transport;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * The UDP pipeline's second thread, where datagrams are decoded and envelopes published to the
 * model. The event loop receives each datagram (the system call, the copy, the time stamp, the
 * classification) and hands it here, where it is decoded and the model's work runs (robot
 * registry, option session, traffic meter, view stores, recorder): on two cores the two halves
 * run side by side, each about half the work (measured: the event loop ~1.8 µs, this thread
 * ~2.1 µs per datagram; with decoding on the event loop it was 2.8 and 1.5, docs/benchmarks.md,
 * issue 11). With a team key each datagram's tag and counter are checked here too, in arrival
 * order with the reliable stream's segments that share the robot's counter (their check and
 * their stop-and-wait input are handed over here as {@link #addTask tasks}); a forgery is
 * published as such, without its message. While this thread is the slower one the event loop
 * takes the HMACs on ({@link #behind}, issue 15). One thread and one
 * FIFO queue: the order of the envelopes and tasks is the order of the datagrams. Handed over in batches (one per
 * socket read), so the wake-up costs once per batch, not per datagram. Bounded: when
 * {@link #CAPACITY} batches wait, the event loop waits too and the datagrams stay in the
 * socket's receive buffer.
 */
final class DecodeStage implements AutoCloseable {

    static final int CAPACITY = 256;
    private static final int MAX_BATCH = 64;
    private static final List<Object> STOP = List.of();

    private final BlockingQueue<List<Object>> queue = new ArrayBlockingQueue<>(CAPACITY);
    /** Event loop: whether a whole batch still waited for this thread at the last hand-over. */
    private boolean behind;
    private final EnvelopeSink sink;
    private final Thread thread;
    /** Envelopes decoded on the event loop, the work that makes one here, tasks (or an {@link #awaitPublished} marker). */
    private List<Object> batch = new ArrayList<>(MAX_BATCH);
    private volatile boolean closed;
    /** This thread's kernel id, once it runs (Linux; empty elsewhere): for {@link CoreSplit}. */
    private final java.util.concurrent.CompletableFuture<java.util.Optional<String>> threadId =
            new java.util.concurrent.CompletableFuture<>();

    DecodeStage(EnvelopeSink sink) {
        this.sink = sink;
        this.thread = new Thread(this::run, "touchline-decode");
        thread.setDaemon(true);
    }

    /** Starts the publishing thread (from the thread whose CPUs it should share: {@link CoreSplit}). */
    DecodeStage start() {
        thread.start();
        return this;
    }

    /** This thread's kernel id (waits until the thread has started), empty where there is none. */
    java.util.Optional<String> threadId() {
        return threadId.join();
    }

    /** Event loop: one datagram's remaining work (decode, envelope), published in order. */
    void add(Supplier<Envelope> work) {
        append(work);
    }

    /** Event loop: one decoded envelope, published in order. */
    void add(Envelope decoded) {
        append(decoded);
    }

    /** Event loop: work that runs here in order with the envelopes (and publishes what it has to itself). */
    void addTask(Runnable task) {
        append(task);
    }

    private void append(Object item) {
        batch.add(item);
        if (batch.size() >= MAX_BATCH) {
            flush();
        }
    }

    /**
     * Event loop: true when this thread had not yet taken the previous batch at the last
     * hand-over, i.e. it is the slower of the two; the event loop then takes on work that needs
     * no order (the tags' HMAC, issue 15), so the two share it by how busy they are.
     */
    boolean behind() {
        return behind;
    }

    /** Event loop: hands the batch over (at the end of each socket read). */
    void flush() {
        if (batch.isEmpty()) {
            return;
        }
        List<Object> full = batch;
        batch = new ArrayList<>(MAX_BATCH);
        behind = !queue.isEmpty();
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

    /**
     * Returns once everything handed over before has been published (call after the event loop's
     * last {@link #flush}, e.g. when reading was stopped): a marker goes through the queue.
     */
    void awaitPublished() throws InterruptedException {
        java.util.concurrent.CountDownLatch published = new java.util.concurrent.CountDownLatch(1);
        queue.put(List.of(published));
        published.await();
    }

    @SuppressWarnings("unchecked") // the batch holds Envelopes, Supplier<Envelope>s and Runnables only
    private void run() {
        threadId.complete(CoreSplit.currentThreadId());
        while (true) {
            List<Object> work;
            try {
                work = queue.take();
            } catch (InterruptedException e) {
                return;
            }
            if (work == STOP) {
                return;
            }
            for (Object w : work) {
                if (w instanceof java.util.concurrent.CountDownLatch published) {
                    published.countDown();
                    continue;
                }
                try {
                    if (w instanceof Runnable task) {
                        task.run();
                        continue;
                    }
                    sink.accept(w instanceof Envelope e ? e : ((Supplier<Envelope>) w).get());
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
