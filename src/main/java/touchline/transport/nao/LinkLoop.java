package touchline.transport.nao;

import touchline.transport.MonotonicClock;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.Pipe;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The thread of a NAO link ({@code nao-link-HOST:PORT}) and the lock that guards its
 * {@link NaoConnection} and {@link CallDispatcher} (ZeroMQ sockets are not thread-safe). The
 * thread makes the dispatcher's turns; between two turns it waits without the lock, in a
 * selector on the sockets' signalling file descriptors (ZeroMQ's ZMQ_FD contract) and a
 * wake-up pipe, until a reply, a connection event, a caller's wake-up or the next timer. A
 * caller that may send and finds the lock free sends its call itself, at once ({@link #submit}),
 * instead of queueing it and waking the thread (a thread wake-up costs about as much as a
 * loopback round trip); any other caller queues the call and wakes the thread. The console's
 * sessions never send on the caller's thread ({@link NaoLink#queueEveryCall}): a click only
 * enqueues.
 */
final class LinkLoop {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(LinkLoop.class);

    private final String peer;
    private final NaoConnection connection;
    private final CallDispatcher dispatcher;
    private final MonotonicClock clock;
    private final ReentrantLock lock = new ReentrantLock();
    private final Pipe wakePipe;
    private final AtomicBoolean wakePending = new AtomicBoolean();
    private final Thread thread;
    // When the thread will make its next turn (monotonic); a caller that adds an earlier timer wakes it.
    private volatile long nextTurnNanos;
    private volatile boolean running = true;
    private volatile String closedBecause = "link closed";
    private boolean started;  // guarded by this
    private boolean closing;  // guarded by this
    private final CompletableFuture<Void> stopped = new CompletableFuture<>();

    /** @param peer "host:port", for the thread's name and the log */
    LinkLoop(String peer, NaoConnection connection, CallDispatcher dispatcher, MonotonicClock clock) {
        this.peer = peer;
        this.connection = connection;
        this.dispatcher = dispatcher;
        this.clock = clock;
        try {
            wakePipe = Pipe.open();
            wakePipe.source().configureBlocking(false);
            wakePipe.sink().configureBlocking(false);
        } catch (IOException e) {
            throw new IllegalStateException("cannot create the link's wake-up pipe", e);
        }
        thread = new Thread(this::run, "nao-link-" + peer);
        thread.setDaemon(true);
    }

    /** Starts the link's thread (once; not after {@link #close}). */
    synchronized void start() {
        if (!started && !closing) {
            started = true;
            thread.start();
        }
    }

    boolean running() {
        return running;
    }

    /** Why the link ended, for calls made after. */
    String closedBecause() {
        return closedBecause;
    }

    /**
     * With {@code callerMaySend}: sends at once on the caller's thread if the lock is free
     * (never on a thread already inside the link, a callback of a completed call: the dispatcher
     * would be re-entered). Otherwise, or when the lock is busy, queues the call and wakes the
     * link thread, which sends it.
     */
    void submit(QueuedCall s, boolean callerMaySend) {
        if (callerMaySend && !lock.isHeldByCurrentThread() && lock.tryLock()) {
            try {
                if (connection.isOpen()) {
                    dispatcher.drainSubmissions(); // calls queued before this one go first
                    dispatcher.dispatch(s);
                    // A reply that arrived meanwhile (its signal consumed by the send), or a
                    // timer earlier than the thread's next turn, needs the link thread.
                    if (connection.replyWaiting() || dispatcher.nextTurnNanos(clock.nanoTime()) - nextTurnNanos < 0) {
                        wake();
                    }
                    return;
                }
                if (!running) {
                    s.end(new CallOutcome.Lost(closedBecause));
                    return;
                }
            } finally {
                lock.unlock();
            }
        }
        dispatcher.queue(s);
        wake();
    }

    /**
     * Asks the thread to stop and returns at once (never waits for it: the caller may be the
     * window's thread): the thread ends every call still open as lost, shuts the connection and
     * then completes {@link #stopped()}. False when the loop was already closed.
     */
    boolean close() {
        synchronized (this) {
            if (closing) {
                return false;
            }
            closing = true;
            running = false;
            if (!started) { // no thread to do it
                locked(() -> dispatcher.endCalls(closedBecause));
                closePipe();
                stopped.complete(null);
                return true;
            }
        }
        wake();
        return true;
    }

    /** Completes (on the link's thread) once the loop has stopped and let go of its connection. */
    CompletionStage<Void> stopped() {
        return stopped.minimalCompletionStage();
    }

    private void closePipe() {
        try {
            wakePipe.sink().close();
            wakePipe.source().close();
        } catch (IOException ignored) {
            // closing a pipe we own; nothing to report
        }
    }

    private void wake() {
        if (wakePending.compareAndSet(false, true)) {
            try {
                synchronized (wakePipe) {
                    wakePipe.sink().write(ByteBuffer.wrap(new byte[] {1}));
                }
            } catch (IOException e) {
                // the pipe is closed only after the thread stopped; nothing left to wake
            }
        }
    }

    private void run() {
        Selector selector = null;
        try {
            selector = Selector.open();
            wakePipe.source().register(selector, SelectionKey.OP_READ);
            ByteBuffer drain = ByteBuffer.allocate(64);
            locked(connection::open);
            while (running) {
                long timeoutMillis;
                lock.lock();
                try {
                    long next = dispatcher.turn();
                    connection.registerIfReplaced(selector);
                    nextTurnNanos = next;
                    timeoutMillis = Math.max(0, TimeUnit.NANOSECONDS.toMillis(next - clock.nanoTime() + 999_999));
                } finally {
                    lock.unlock();
                }
                // Without the lock: callers send meanwhile. Readable = a signal on a socket's
                // mailbox (a reply or an event) or a wake-up from a caller.
                if (timeoutMillis == 0) {
                    selector.selectNow();
                } else {
                    selector.select(timeoutMillis);
                }
                selector.selectedKeys().clear();
                wakePending.set(false);
                drain.clear();
                while (wakePipe.source().read(drain) > 0) {
                    drain.clear();
                }
            }
        } catch (RuntimeException | IOException | AssertionError | LinkageError e) {
            // An Error too (JeroMQ's asserts under -ea): the link must end saying why, never die silently.
            LOG.error("NAO link thread for {} failed", peer, e);
            closedBecause = "link thread failed: " + e;
        } finally {
            running = false;
            locked(() -> {
                dispatcher.endCalls(closedBecause);
                connection.shutdown();
            });
            try {
                if (selector != null) {
                    selector.close();
                }
            } catch (IOException ignored) {
                // closing our own selector at exit
            }
            locked(() -> dispatcher.closed(closedBecause));
            closePipe();
            stopped.complete(null);
        }
    }

    private void locked(Runnable action) {
        lock.lock();
        try {
            action.run();
        } finally {
            lock.unlock();
        }
    }
}
