package touchline.transport.nao;

import touchline.transport.MonotonicClock;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.Pipe;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The thread of a NAO link ({@code nao-link-HOST:PORT}) and the lock that guards its
 * {@link NaoConnection} and {@link CallDispatcher} (ZeroMQ sockets are not thread-safe). The
 * thread makes the dispatcher's turns; between two turns it waits without the lock, in a
 * selector on the sockets' signalling file descriptors (ZeroMQ's ZMQ_FD contract) and a
 * wake-up pipe, until a reply, a connection event, a caller's wake-up or the next timer. A
 * caller that finds the lock free sends its call itself, at once ({@link #submit}), instead of
 * queueing it and waking the thread (a thread wake-up costs about as much as a loopback round
 * trip); a caller that finds it busy queues the call and wakes the thread.
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
    private final AtomicBoolean closing = new AtomicBoolean();

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

    void start() {
        thread.start();
    }

    boolean running() {
        return running;
    }

    /** Why the link ended, for calls made after. */
    String closedBecause() {
        return closedBecause;
    }

    /**
     * Sends at once on the caller's thread if the lock is free, else queues for the link
     * thread. Not on a thread already inside the link (a callback of a completed call): the
     * dispatcher would be re-entered.
     */
    void submit(QueuedCall s) {
        if (!lock.isHeldByCurrentThread() && lock.tryLock()) {
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
     * Stops the thread (waiting up to 3 s for it): every call still open ends as lost. False
     * when the loop was already closed.
     */
    boolean close() {
        if (!closing.compareAndSet(false, true)) {
            return false;
        }
        running = false;
        wake();
        try {
            thread.join(3000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try {
            wakePipe.sink().close();
            wakePipe.source().close();
        } catch (IOException ignored) {
            // closing a pipe we own; nothing to report
        }
        return true;
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
