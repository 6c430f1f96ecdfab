package touchline.transport.nao;

import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.protocol.nao.MixedValueCodec;
import touchline.protocol.nao.MixedValueException;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.MicrosClock;
import touchline.transport.SendGate;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.Pipe;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The console's RPC link to one NAO's {@code HAWActorRPC} module over ZeroMQ: the facade
 * callers use, and the link thread that drives its parts.
 *
 * <p>The parts, each readable alone: {@link NaoConnection} (the JeroMQ DEALER and its socket
 * monitor: heartbeats, CURVE), {@link ConnectionWatch} (the connection state from the
 * monitor's events and time), {@link ReplyReader} (reply frames to request id and outcome),
 * {@link PendingCalls} (the call table: request ids, attempt
 * deadlines, stray replies), {@link CallPacing} (per-method minimum intervals, coalescing to
 * the newest call). ZeroMQ sockets are not thread-safe, so the connection and all call state
 * are guarded by one lock, and a thread ({@code nao-link-HOST:PORT}) reads replies,
 * connection events and timers. It waits for them without the lock, in a selector on the
 * sockets' signalling file descriptors (ZeroMQ's ZMQ_FD contract), so a caller that finds
 * the lock free sends its request itself, at once, instead of queueing it and waking the
 * link thread (a thread wake-up costs about as much as a loopback round trip); a caller
 * that finds it busy queues the call and wakes the thread. {@link #call} returns a future
 * that always completes with a {@link CallOutcome}, never exceptionally. Many calls are in
 * flight at once: each request goes out as {@code [requestId][""][HAWActorRPCRequest]} and
 * replies, which the robot's load-balancing broker returns out of order, are matched by id;
 * a reply whose id is no longer pending (it timed out) is counted and dropped.
 *
 * <p>Liveness: the ZMTP handshake, not the TCP connect, makes the state
 * {@link ConnectionState#ONLINE}; a disconnect or heartbeat timeout makes it
 * {@link ConnectionState#LOST}: every pending, waiting or paced call then ends as
 * {@link CallOutcome.Lost} and the connection is reopened, so nothing queued can run when the
 * robot comes back. While LOST new calls fail at once; while first CONNECTING they wait for
 * ONLINE within their timeout. Every request also carries {@code deadlineMillis} (now +
 * timeout) so the robot drops it when late.
 *
 * <p>Rules from {@link NaoLinkConfig}: per-method timeouts; retries (a resend under a new id)
 * only for idempotent methods; per-method minimum intervals ({@link CallPacing}). A send gate
 * ({@link #setSendGate}, match mode) holds back every call, reads included ("during play only
 * the GameController talks to the robots"), with {@link CallOutcome.HeldBack}; nothing held
 * back is queued for later.
 *
 * <p>Each request (OUT), reply (IN) and connection event ({@link Channel#LINK_EVENT}) is
 * published through a {@link NaoEnvelopeChannel} into the Envelope stream.
 */
public final class NaoLink implements AutoCloseable {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(NaoLink.class);

    private final String host;
    private final int port;
    private final InetSocketAddress peer;
    private final NaoLinkConfig config;
    private final NaoEnvelopeChannel envelopes;
    private final boolean ownsEnvelopes;
    private final MicrosClock clock;
    private final MixedValueCodec codec = new MixedValueCodec();
    private final ReplyReader replies = new ReplyReader();
    private final NaoConnection connection;
    // Written under lock, read anywhere.
    private final ConnectionWatch watch;
    private final ConcurrentLinkedQueue<QueuedCall> submissions = new ConcurrentLinkedQueue<>();
    private final Pipe wakePipe;
    private final AtomicBoolean wakePending = new AtomicBoolean();
    private final Thread thread;
    // Guards the connection and every field marked "under lock" below.
    private final ReentrantLock lock = new ReentrantLock();
    // When the link thread will wake next (System.nanoTime); a caller that adds an earlier
    // timer wakes it.
    private volatile long linkWakeAtNanos;
    private final List<Consumer<ConnectionState>> stateListeners = new CopyOnWriteArrayList<>();
    private volatile boolean running = true;
    private volatile SendGate gate = SendGate.open();

    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong answered = new AtomicLong();
    private final AtomicLong lostCalls = new AtomicLong();
    private final AtomicLong retried = new AtomicLong();

    // Under lock.
    private final PendingCalls pending = new PendingCalls();
    private final CallPacing pacing;
    private final List<QueuedCall> awaitingOnline = new ArrayList<>();
    // Link thread only.
    private Selector selector;
    private volatile String closedBecause = "link closed";
    private final AtomicBoolean closing = new AtomicBoolean();

    /** Connects to {@code host:port}, insecure, and publishes into its own pipeline ending in {@code sink}. */
    public NaoLink(String host, int port, NaoLinkConfig config, touchline.transport.EnvelopeSink sink) {
        this(host, port, config, new NaoEnvelopeChannel(sink), true, null, NaoEnvelopeChannel::nowMicros);
    }

    /**
     * Connects to {@code host:port} and publishes into its own pipeline ending in {@code sink}.
     *
     * @param keys CURVE client keys (the NAO link encrypted, the robot side checks our key), or null: insecure
     */
    public NaoLink(String host, int port, NaoLinkConfig config, touchline.transport.EnvelopeSink sink,
                   NaoClientKeys keys) {
        this(host, port, config, new NaoEnvelopeChannel(sink), true, keys, NaoEnvelopeChannel::nowMicros);
    }

    /** Connects to {@code host:port}, insecure, and publishes into a shared pipeline (e.g. with the camera stream). */
    public NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes) {
        this(host, port, config, envelopes, false, null, NaoEnvelopeChannel::nowMicros);
    }

    /** As above with CURVE client keys, or null for insecure. */
    public NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, NaoClientKeys keys) {
        this(host, port, config, envelopes, false, keys, NaoEnvelopeChannel::nowMicros);
    }

    /** As above, time-stamping envelopes with {@code clock} (the console's). */
    public NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, NaoClientKeys keys,
                   MicrosClock clock) {
        this(host, port, config, envelopes, false, keys, clock);
    }

    private NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, boolean owns,
                    NaoClientKeys keys, MicrosClock clock) {
        this.host = host;
        this.port = port;
        this.peer = InetSocketAddress.createUnresolved(host, port);
        this.config = config;
        this.envelopes = envelopes;
        this.ownsEnvelopes = owns;
        this.clock = clock;
        this.connection = new NaoConnection(host, port, keys);
        this.watch = new ConnectionWatch(keys != null, host + ":" + port);
        this.pacing = new CallPacing(config);
        try {
            wakePipe = Pipe.open();
            wakePipe.source().configureBlocking(false);
            wakePipe.sink().configureBlocking(false);
        } catch (IOException e) {
            throw new IllegalStateException("cannot create the link's wake-up pipe", e);
        }
        thread = new Thread(this::run, "nao-link-" + host + ":" + port);
        thread.setDaemon(true);
        thread.start();
    }

    public String host() {
        return host;
    }

    public int port() {
        return port;
    }

    public NaoLinkConfig config() {
        return config;
    }

    /** Whether the link uses CURVE (encrypted, our key checked by the robot side). */
    public boolean secure() {
        return connection.secure();
    }

    /**
     * Why the CURVE handshake fails, in words for the user ("the NAO refused our key: give it
     * console.public — see docs/security.md"); "" when it did not fail. Goes with
     * {@link ConnectionState#REFUSED}.
     */
    public String securityProblem() {
        return watch.securityProblem();
    }

    public ConnectionState state() {
        return watch.state();
    }

    /** Called on the link thread at each change; must not block. Close the handle to stop. */
    public AutoCloseable onStateChange(Consumer<ConnectionState> listener) {
        stateListeners.add(listener);
        return () -> stateListeners.remove(listener);
    }

    /**
     * Match mode hook: while {@code mayRobotBeCommanded} is false, every call ends at once as
     * {@link CallOutcome.HeldBack} with {@code reason} and nothing is sent. Checked on the
     * caller's thread when the call is made.
     */
    public void setSendGate(BooleanSupplier mayRobotBeCommanded, Supplier<String> reason) {
        setSendGate(() -> mayRobotBeCommanded.getAsBoolean() ? Optional.empty() : Optional.of(reason.get()));
    }

    /**
     * As above with the console's gate: asked once per call (asking may count the call as held
     * back), a reason means {@link CallOutcome.HeldBack} with that reason.
     */
    public void setSendGate(SendGate gate) {
        this.gate = gate;
    }

    /**
     * Calls with the configured timeout for the method. The future completes on the link
     * thread, or on a calling thread for outcomes decided as a call is made (held back,
     * superseded, lost): dependent actions must not block (hand off to another executor if
     * they do).
     */
    public CompletableFuture<CallOutcome> call(NaoCall call) {
        return call(call, config.timeoutMillis(call));
    }

    public CompletableFuture<CallOutcome> call(String module, String method, Object... params) {
        return call(NaoCall.of(module, method, params));
    }

    public CompletableFuture<CallOutcome> call(NaoCall call, long timeoutMillis) {
        long now = System.nanoTime();
        CompletableFuture<CallOutcome> future = new CompletableFuture<>();
        if (!running) {
            future.complete(new CallOutcome.Lost(closedBecause));
            return future;
        }
        Optional<String> held = gate.holdReason();
        if (held.isPresent()) {
            future.complete(new CallOutcome.HeldBack(held.get()));
            return future;
        }
        HAWActorRPCRequest.Builder request;
        try {
            request = HAWActorRPCRequest.newBuilder().setModule(call.module()).setMethod(call.method())
                    .addAllParams(codec.encodeAll(call.params()));
        } catch (MixedValueException e) {
            future.complete(new CallOutcome.Failed("cannot send parameters: " + e.getMessage()));
            return future;
        }
        submit(new QueuedCall(call, request, timeoutMillis, config.isIdempotent(call), future, now));
        return future;
    }

    /**
     * Sends at once on the caller's thread if the lock is free, else queues for the link
     * thread. Not on a thread already inside the link (a callback of a completed call): the
     * link's loops would be re-entered.
     */
    private void submit(QueuedCall s) {
        if (!lock.isHeldByCurrentThread() && lock.tryLock()) {
            try {
                if (connection.isOpen()) {
                    drainSubmissions(); // calls queued before this one go first
                    dispatch(s);
                    // A reply that arrived meanwhile (its signal consumed by the send), or a
                    // timer earlier than the thread's next wake, needs the link thread.
                    if (connection.replyWaiting() || nextWakeNanos(System.nanoTime()) - linkWakeAtNanos < 0) {
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
        submissions.add(s);
        wake();
    }

    /**
     * Runs the calls one after the other, each after the previous one succeeded; stops at
     * the first failure (whose outcome is the last in the result). Never completes exceptionally.
     */
    public CompletableFuture<SequenceOutcome> sequence(List<NaoCall> calls) {
        List<CallOutcome> outcomes = new ArrayList<>();
        CompletableFuture<SequenceOutcome> result = new CompletableFuture<>();
        runStep(calls, 0, outcomes, result);
        return result;
    }

    private void runStep(List<NaoCall> calls, int index, List<CallOutcome> outcomes,
                         CompletableFuture<SequenceOutcome> result) {
        if (index == calls.size()) {
            result.complete(new SequenceOutcome(calls, outcomes));
            return;
        }
        call(calls.get(index)).thenAccept(outcome -> {
            outcomes.add(outcome);
            if (outcome.ok()) {
                runStep(calls, index + 1, outcomes, result);
            } else {
                result.complete(new SequenceOutcome(calls, outcomes));
            }
        });
    }

    /** Counters since start, for the status bar and tests. */
    public LinkStats stats() {
        return new LinkStats(sent.get(), answered.get(), pending.timeouts() + pacing.timeouts(), pending.strays(),
                replies.malformed(), lostCalls.get(), retried.get());
    }

    /**
     * Counters of a link. {@code stray}: replies for calls that had already timed out;
     * {@code malformed}: replies that could not be read; {@code lost}: calls failed by a lost connection.
     */
    public record LinkStats(long sent, long replies, long timeouts, long stray, long malformed, long lost,
                            long retried) {
    }

    @Override
    public void close() {
        if (!closing.compareAndSet(false, true)) {
            return;
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
        if (ownsEnvelopes) {
            envelopes.close();
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

    // ---------------------------------------------------------------- link thread

    private void run() {
        try {
            selector = Selector.open();
            wakePipe.source().register(selector, SelectionKey.OP_READ);
            ByteBuffer drain = ByteBuffer.allocate(64);
            lock.lock();
            try {
                connection.open();
            } finally {
                lock.unlock();
            }
            while (running) {
                long timeoutMillis;
                lock.lock();
                try {
                    // Read both sockets on every pass, not only when the selector flagged them:
                    // JeroMQ was seen to miss a monitor event's signal.
                    readMonitor();
                    readReplies();
                    drainSubmissions();
                    long now = System.nanoTime();
                    runTimers(now);
                    connection.registerIfReplaced(selector);
                    long next = nextWakeNanos(now);
                    linkWakeAtNanos = next;
                    timeoutMillis = Math.max(0, TimeUnit.NANOSECONDS.toMillis(next - now + 999_999));
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
            LOG.error("NAO link thread for {}:{} failed", host, port, e);
            closedBecause = "link thread failed: " + e;
        } finally {
            running = false;
            lock.lock();
            try {
                failAll(new CallOutcome.Lost(closedBecause));
                QueuedCall s;
                while ((s = submissions.poll()) != null) {
                    s.end(new CallOutcome.Lost(closedBecause));
                }
                connection.shutdown();
            } finally {
                lock.unlock();
            }
            try {
                if (selector != null) {
                    selector.close();
                }
            } catch (IOException ignored) {
                // closing our own selector at exit
            }
            lock.lock();
            try {
                apply(watch.closed(closedBecause));
            } finally {
                lock.unlock();
            }
        }
    }

    private void drainSubmissions() {
        QueuedCall s;
        while ((s = submissions.poll()) != null) {
            dispatch(s);
        }
    }

    /** When the link thread must next look at the timers. Under lock. */
    private long nextWakeNanos(long now) {
        long next = pending.nextDeadline(now + TimeUnit.MILLISECONDS.toNanos(200));
        for (QueuedCall s : awaitingOnline) {
            next = Math.min(next, s.deadlineNanos());
        }
        return pacing.nextDue(next);
    }

    private void dispatch(QueuedCall s) {
        if (s.future().isDone()) {
            return;
        }
        ConnectionState state = watch.state();
        if (state == ConnectionState.LOST || state == ConnectionState.CLOSED) {
            lose(s, "robot not connected");
            return;
        }
        if (state == ConnectionState.REFUSED) {
            lose(s, watch.securityProblem());
            return;
        }
        if (pacing.holdIfEarly(s, System.nanoTime())) {
            return;
        }
        if (state == ConnectionState.CONNECTING) {
            awaitingOnline.add(s);
            return;
        }
        send(s, 1);
    }

    private void send(QueuedCall s, int attempt) {
        long now = System.nanoTime();
        long remaining = s.idempotent() ? s.timeoutMillis()
                : Math.max(1, TimeUnit.NANOSECONDS.toMillis(s.deadlineNanos() - now));
        HAWActorRPCRequest request = s.request().setDeadlineMillis(System.currentTimeMillis() + remaining).build();
        byte[] payload = request.toByteArray();
        long id = pending.nextId();
        if (!connection.send(id, payload)) {
            // With immediate=1 semantics there is no pipe without a live peer: nothing was queued.
            lose(s, "no connection to send on");
            return;
        }
        sent.incrementAndGet();
        pacing.sent(s.call(), now);
        pending.sent(id, s, now + TimeUnit.MILLISECONDS.toNanos(remaining), attempt);
        envelopes.publish(new Envelope(clock.nowMicros(), Direction.OUT, Channel.NAO_RPC, peer, Envelope.NO_ROBOT,
                s.call().qualifiedName(), request, payload, null));
    }

    private void readReplies() {
        List<byte[]> frames;
        while ((frames = connection.receive()) != null) {
            handleReply(frames);
        }
    }

    private void handleReply(List<byte[]> frames) {
        byte[] payload = frames.get(frames.size() - 1);
        ReplyReader.Read read = replies.read(frames);
        if (read instanceof ReplyReader.Malformed m) {
            envelopes.publish(new Envelope(clock.nowMicros(), Direction.IN, Channel.NAO_RPC, peer, Envelope.NO_ROBOT,
                    "malformed", null, payload, m.why()));
            PendingCalls.Sent p = m.id() < 0 ? null : pending.unreadable(m.id());
            if (p != null) {
                p.call().end(new CallOutcome.Failed(m.callError()));
            }
            return;
        }
        ReplyReader.Reply reply = (ReplyReader.Reply) read;
        PendingCalls.Sent p = pending.answered(reply.id());
        String kind = p == null ? "stray" : p.call().call().qualifiedName();
        envelopes.publish(new Envelope(clock.nowMicros(), Direction.IN, Channel.NAO_RPC, peer, Envelope.NO_ROBOT,
                kind, reply.response(), payload, null));
        if (p == null) {
            return;
        }
        answered.incrementAndGet();
        watch.replied();
        p.call().end(replies.outcomeOf(reply.response()));
    }

    private void readMonitor() {
        NaoConnection.Event event;
        while ((event = connection.nextEvent()) != null) {
            List<ConnectionWatch.Transition> changes = watch.onEvent(event, System.nanoTime());
            apply(changes);
            if (changes.stream().anyMatch(t -> t.to() == ConnectionState.LOST)) {
                return; // the monitor socket was replaced
            }
        }
    }

    /** Acts on state changes: announces each; online sends the waiting calls, lost and refused end every call. */
    private void apply(List<ConnectionWatch.Transition> changes) {
        for (ConnectionWatch.Transition t : changes) {
            announce(t.to(), t.why());
            switch (t.to()) {
                case ONLINE -> {
                    List<QueuedCall> waiting = new ArrayList<>(awaitingOnline);
                    awaitingOnline.clear();
                    for (QueuedCall s : waiting) {
                        send(s, 1);
                    }
                }
                case LOST -> {
                    failAll(new CallOutcome.Lost(t.why()));
                    // Close and reopen: whatever the old socket still held can never reach the robot.
                    connection.reopen();
                }
                case REFUSED -> failAll(new CallOutcome.Lost(t.why()));
                default -> { }
            }
        }
    }

    private void failAll(CallOutcome.Lost outcome) {
        long n = pending.failAll(outcome) + pacing.failAll(outcome) + awaitingOnline.size();
        for (QueuedCall s : awaitingOnline) {
            s.end(outcome);
        }
        awaitingOnline.clear();
        lostCalls.addAndGet(n);
    }

    private void lose(QueuedCall s, String why) {
        lostCalls.incrementAndGet();
        s.end(new CallOutcome.Lost(why));
    }

    private void runTimers(long now) {
        apply(watch.onTime(now));
        for (PendingCalls.Sent p : pending.expired(now)) {
            QueuedCall s = p.call();
            if (s.idempotent() && p.attempt() <= config.retries() && watch.state() == ConnectionState.ONLINE) {
                retried.incrementAndGet();
                send(s, p.attempt() + 1);
            } else {
                pending.timeOut(s, System.nanoTime());
            }
        }
        for (Iterator<QueuedCall> it = awaitingOnline.iterator(); it.hasNext(); ) {
            QueuedCall s = it.next();
            if (now - s.deadlineNanos() >= 0) {
                it.remove();
                lose(s, "no connection within " + s.timeoutMillis() + " ms");
            }
        }
        for (QueuedCall s : pacing.due(now)) {
            ConnectionState state = watch.state();
            if (state == ConnectionState.ONLINE) {
                send(s, 1);
            } else if (state == ConnectionState.CONNECTING) {
                awaitingOnline.add(s);
            } else {
                lose(s, "robot not connected");
            }
        }
    }

    private void announce(ConnectionState next, String why) {
        String text = "nao " + host + ":" + port + " " + next.name().toLowerCase() + ": " + why;
        LOG.info(text);
        envelopes.publish(new Envelope(clock.nowMicros(), Direction.IN, Channel.LINK_EVENT, peer, Envelope.NO_ROBOT,
                "nao." + next.name().toLowerCase(), null, text.getBytes(StandardCharsets.UTF_8), null));
        for (Consumer<ConnectionState> l : stateListeners) {
            try {
                l.accept(next);
            } catch (RuntimeException e) {
                LOG.warn("connection state listener failed: {}", e.toString());
            }
        }
    }
}
