package touchline.transport.nao;

import com.google.protobuf.InvalidProtocolBufferException;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.protocol.nao.MixedValueCodec;
import touchline.protocol.nao.MixedValueException;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.Pipe;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
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
 * The console's RPC link to one NAO's {@code HAWActorRPC} module over ZeroMQ.
 *
 * <p>One JeroMQ DEALER. ZeroMQ sockets are not thread-safe, so the socket and all call
 * state are guarded by one lock, and a thread ({@code nao-link-HOST:PORT}) reads replies,
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
 * <p>Liveness: {@code setImmediate(false)} (in JeroMQ this is libzmq's ZMQ_IMMEDIATE=1:
 * queue only on completed connections, so nothing waits in a pipe for a dead robot), ZMTP
 * heartbeats (500 ms interval, 1500 ms timeout) and a socket monitor. The ZMTP handshake,
 * not the TCP connect, makes the state {@link ConnectionState#ONLINE}; a disconnect or
 * heartbeat timeout makes it {@link ConnectionState#LOST}: every pending, waiting or
 * rate-limited call then ends as {@link CallOutcome.Lost} and the socket is closed and
 * reopened, so nothing queued can run when the robot comes back. While LOST new calls fail
 * at once; while first CONNECTING they wait for ONLINE within their timeout. Every request
 * also carries {@code deadlineMillis} (now + timeout) so the robot drops it when late.
 *
 * <p>Rules from {@link NaoLinkConfig}: per-method timeouts; retries (a resend under a new id)
 * only for idempotent methods; per-method minimum intervals, enforced by coalescing: a call
 * inside the interval waits for its end, and a newer call of the same method replaces it
 * (the older ends as {@link CallOutcome.Superseded}). Coalescing rather than rejecting keeps
 * the robot's last target the user's last input: a "stop walking" right after a "walk" must
 * not be dropped. A send gate ({@link #setSendGate}, match mode) holds back every call, reads
 * included ("during play only the GameController talks to the robots"), with
 * {@link CallOutcome.HeldBack}; nothing held back is queued for later.
 *
 * <p>Each request (OUT), reply (IN) and connection event ({@link Channel#LINK_EVENT}) is
 * published through a {@link NaoEnvelopeChannel} into the Envelope stream.
 */
public final class NaoLink implements AutoCloseable {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(NaoLink.class);
    private static final AtomicLong MONITOR_IDS = new AtomicLong();
    static final int HEARTBEAT_IVL_MS = 500;
    static final int HEARTBEAT_TIMEOUT_MS = 1500;
    static final int HEARTBEAT_TTL_MS = 3000;
    static final int HANDSHAKE_IVL_MS = 2000;

    private final String host;
    private final int port;
    private final InetSocketAddress peer;
    private final NaoLinkConfig config;
    private final NaoEnvelopeChannel envelopes;
    private final boolean ownsEnvelopes;
    private final MixedValueCodec codec = new MixedValueCodec();
    private final ZContext zmq = new ZContext(1);
    private final NaoClientKeys keys;
    private volatile String securityProblem = "";
    // Link thread only: connections dropped right after the greeting without a reply, with CURVE on.
    private int disconnectsBeforeHandshake;
    private long handshakeAtNanos;
    private boolean repliedSinceHandshake;
    // Link thread only: when a REFUSED link that connected again counts as online (0: none).
    private long probationUntilNanos;
    private final ConcurrentLinkedQueue<Submission> submissions = new ConcurrentLinkedQueue<>();
    private final Pipe wakePipe;
    private final AtomicBoolean wakePending = new AtomicBoolean();
    private final Thread thread;
    // Guards the sockets and every field marked "under lock" below.
    private final ReentrantLock lock = new ReentrantLock();
    // When the link thread will wake next (System.nanoTime); a caller that adds an earlier
    // timer wakes it.
    private volatile long linkWakeAtNanos;
    private final List<Consumer<ConnectionState>> stateListeners = new CopyOnWriteArrayList<>();
    private volatile ConnectionState state = ConnectionState.CONNECTING;
    private volatile boolean running = true;
    private volatile BooleanSupplier mayCommand = () -> true;
    private volatile Supplier<String> gateReason = () -> "";

    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong replies = new AtomicLong();
    private final AtomicLong timeouts = new AtomicLong();
    private final AtomicLong strayReplies = new AtomicLong();
    private final AtomicLong malformedReplies = new AtomicLong();
    private final AtomicLong lostCalls = new AtomicLong();
    private final AtomicLong retried = new AtomicLong();

    // Under lock.
    private ZMQ.Socket dealer;
    private ZMQ.Socket monitor;
    private boolean socketsReplaced;
    // Link thread only.
    private Selector selector;
    private SelectionKey dealerKey;
    private SelectionKey monitorKey;
    private long nextRequestId = 1;
    private final Map<Long, Pending> pending = new HashMap<>();
    private final List<Submission> awaitingOnline = new ArrayList<>();
    private final Map<String, Submission> coalesced = new HashMap<>();
    private final Map<String, Long> lastSentNanos = new HashMap<>();

    /** Connects to {@code host:port}, insecure, and publishes into its own pipeline ending in {@code sink}. */
    public NaoLink(String host, int port, NaoLinkConfig config, touchline.transport.EnvelopeSink sink) {
        this(host, port, config, new NaoEnvelopeChannel(sink), true, null);
    }

    /**
     * Connects to {@code host:port} and publishes into its own pipeline ending in {@code sink}.
     *
     * @param keys CURVE client keys (the NAO link encrypted, the robot side checks our key), or null: insecure
     */
    public NaoLink(String host, int port, NaoLinkConfig config, touchline.transport.EnvelopeSink sink,
                   NaoClientKeys keys) {
        this(host, port, config, new NaoEnvelopeChannel(sink), true, keys);
    }

    /** Connects to {@code host:port}, insecure, and publishes into a shared pipeline (e.g. with the camera stream). */
    public NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes) {
        this(host, port, config, envelopes, false, null);
    }

    /** As above with CURVE client keys, or null for insecure. */
    public NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, NaoClientKeys keys) {
        this(host, port, config, envelopes, false, keys);
    }

    private NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, boolean owns,
                    NaoClientKeys keys) {
        this.keys = keys;
        this.host = host;
        this.port = port;
        this.peer = InetSocketAddress.createUnresolved(host, port);
        this.config = config;
        this.envelopes = envelopes;
        this.ownsEnvelopes = owns;
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
        return keys != null;
    }

    /**
     * Why the CURVE handshake fails, in words for the user ("the NAO refused our key: give it
     * console.public — see docs/security.md"); "" when it did not fail. Goes with
     * {@link ConnectionState#REFUSED}.
     */
    public String securityProblem() {
        return securityProblem;
    }

    public ConnectionState state() {
        return state;
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
        this.mayCommand = mayRobotBeCommanded;
        this.gateReason = reason;
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
        boolean idempotent = config.isIdempotent(call);
        if (!running) {
            future.complete(new CallOutcome.Lost("link closed"));
            return future;
        }
        if (!mayCommand.getAsBoolean()) {
            future.complete(new CallOutcome.HeldBack(gateReason.get()));
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
        submit(new Submission(call, request, timeoutMillis, idempotent, future, now));
        return future;
    }

    /**
     * Sends at once on the caller's thread if the lock is free, else queues for the link
     * thread. Not on a thread already inside the link (a callback of a completed call): the
     * link's loops would be re-entered.
     */
    private void submit(Submission s) {
        if (!lock.isHeldByCurrentThread() && lock.tryLock()) {
            try {
                if (dealer != null) {
                    drainSubmissions(); // calls queued before this one go first
                    dispatch(s);
                    // ZMQ_FD contract: the send may have consumed the mailbox signal of a reply
                    // that arrived meanwhile, and then the link thread's selector would not
                    // wake for it; a timer earlier than the thread's next wake needs it too.
                    if ((dealer.getEvents() & ZMQ.Poller.POLLIN) != 0
                            || nextWakeNanos(System.nanoTime()) - linkWakeAtNanos < 0) {
                        wake();
                    }
                    return;
                }
                if (!running) {
                    s.future.complete(new CallOutcome.Lost("link closed"));
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
        return new LinkStats(sent.get(), replies.get(), timeouts.get(), strayReplies.get(),
                malformedReplies.get(), lostCalls.get(), retried.get());
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
        if (!running) {
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

    private record Submission(NaoCall call, HAWActorRPCRequest.Builder request, long timeoutMillis,
                              boolean idempotent, CompletableFuture<CallOutcome> future, long submittedNanos) {
        long deadlineNanos() {
            return submittedNanos + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        }
    }

    private static final class Pending {
        final Submission submission;
        final long attemptDeadlineNanos;
        final int attempt;

        Pending(Submission submission, long attemptDeadlineNanos, int attempt) {
            this.submission = submission;
            this.attemptDeadlineNanos = attemptDeadlineNanos;
            this.attempt = attempt;
        }
    }

    private void run() {
        try {
            selector = Selector.open();
            wakePipe.source().register(selector, SelectionKey.OP_READ);
            ByteBuffer drain = ByteBuffer.allocate(64);
            lock.lock();
            try {
                openSocket();
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
                    if (socketsReplaced) {
                        registerSockets();
                    }
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
        } catch (RuntimeException | IOException e) {
            LOG.error("NAO link thread for {}:{} failed", host, port, e);
        } finally {
            lock.lock();
            try {
                failAll(new CallOutcome.Lost("link closed"));
                Submission s;
                while ((s = submissions.poll()) != null) {
                    s.future.complete(new CallOutcome.Lost("link closed"));
                }
                closeSocket();
            } finally {
                lock.unlock();
            }
            zmq.close();
            try {
                if (selector != null) {
                    selector.close();
                }
            } catch (IOException ignored) {
                // closing our own selector at exit
            }
            setState(ConnectionState.CLOSED, "link closed");
        }
    }

    private void drainSubmissions() {
        Submission s;
        while ((s = submissions.poll()) != null) {
            dispatch(s);
        }
    }

    /** (Re)registers the sockets' signalling descriptors after they were opened. Link thread, under lock. */
    private void registerSockets() throws IOException {
        // A replaced socket's descriptor is closed later, by JeroMQ's reaper thread: drop our
        // keys now rather than select on a dying descriptor until then.
        if (dealerKey != null) {
            dealerKey.cancel();
            monitorKey.cancel();
        }
        dealerKey = dealer.getFD().register(selector, SelectionKey.OP_READ);
        monitorKey = monitor.getFD().register(selector, SelectionKey.OP_READ);
        socketsReplaced = false;
    }

    private void openSocket() throws IOException {
        dealer = zmq.createSocket(SocketType.DEALER);
        dealer.setLinger(0);
        dealer.setImmediate(false);
        dealer.setHeartbeatIvl(HEARTBEAT_IVL_MS);
        dealer.setHeartbeatTimeout(HEARTBEAT_TIMEOUT_MS);
        dealer.setHeartbeatTtl(HEARTBEAT_TTL_MS);
        // A peer that accepts TCP but never completes ZMTP (frozen process, or a stalled accept)
        // is dropped and retried after 2 s instead of libzmq's 30 s default.
        dealer.setHandshakeIvl(HANDSHAKE_IVL_MS);
        dealer.setReconnectIVL(100);
        dealer.setReconnectIVLMax(1000);
        dealer.setSndHWM(10_000);
        dealer.setRcvHWM(10_000);
        if (keys != null) {
            keys.applyTo(dealer);
        }
        String monitorAddress = "inproc://nao-link-monitor-" + MONITOR_IDS.incrementAndGet();
        dealer.monitor(monitorAddress, ZMQ.EVENT_ALL);
        monitor = zmq.createSocket(SocketType.PAIR);
        monitor.connect(monitorAddress);
        dealer.connect("tcp://" + host + ":" + port);
        socketsReplaced = true;
    }

    private void closeSocket() {
        if (dealer != null) {
            dealer.monitor(null, 0);
            zmq.destroySocket(dealer);
            dealer = null;
        }
        if (monitor != null) {
            zmq.destroySocket(monitor);
            monitor = null;
        }
    }

    /** When the link thread must next look at the timers. Under lock. */
    private long nextWakeNanos(long now) {
        long next = now + TimeUnit.MILLISECONDS.toNanos(200);
        for (Pending p : pending.values()) {
            next = Math.min(next, p.attemptDeadlineNanos);
        }
        for (Submission s : awaitingOnline) {
            next = Math.min(next, s.deadlineNanos());
        }
        for (Submission s : coalesced.values()) {
            next = Math.min(next, dueNanos(s));
        }
        return next;
    }

    private long dueNanos(Submission s) {
        Long last = lastSentNanos.get(s.call.qualifiedName());
        long interval = TimeUnit.MILLISECONDS.toNanos(config.minIntervalMillis(s.call));
        return last == null ? 0 : last + interval;
    }

    private void dispatch(Submission s) {
        if (s.future.isDone()) {
            return;
        }
        if (state == ConnectionState.LOST || state == ConnectionState.CLOSED) {
            lose(s, "robot not connected");
            return;
        }
        if (state == ConnectionState.REFUSED) {
            lose(s, securityProblem);
            return;
        }
        long interval = config.minIntervalMillis(s.call);
        if (interval > 0) {
            String name = s.call.qualifiedName();
            Long last = lastSentNanos.get(name);
            long now = System.nanoTime();
            if (last != null && now - last < TimeUnit.MILLISECONDS.toNanos(interval)) {
                Submission older = coalesced.put(name, s);
                if (older != null && older != s) {
                    older.future.complete(new CallOutcome.Superseded());
                }
                return;
            }
        }
        if (state == ConnectionState.CONNECTING) {
            awaitingOnline.add(s);
            return;
        }
        send(s, 1);
    }

    private void send(Submission s, int attempt) {
        long now = System.nanoTime();
        long remaining = s.idempotent ? s.timeoutMillis
                : Math.max(1, TimeUnit.NANOSECONDS.toMillis(s.deadlineNanos() - now));
        HAWActorRPCRequest request = s.request.setDeadlineMillis(System.currentTimeMillis() + remaining).build();
        byte[] payload = request.toByteArray();
        long id = nextRequestId++;
        byte[] idBytes = ByteBuffer.allocate(8).putLong(id).array();
        boolean ok = dealer.send(idBytes, ZMQ.SNDMORE | ZMQ.DONTWAIT)
                && dealer.send(new byte[0], ZMQ.SNDMORE | ZMQ.DONTWAIT)
                && dealer.send(payload, ZMQ.DONTWAIT);
        if (!ok) {
            // With immediate=1 semantics there is no pipe without a live peer: nothing was queued.
            lose(s, "no connection to send on");
            return;
        }
        sent.incrementAndGet();
        lastSentNanos.put(s.call.qualifiedName(), now);
        pending.put(id, new Pending(s, now + TimeUnit.MILLISECONDS.toNanos(remaining), attempt));
        envelopes.publish(new Envelope(micros(), Direction.OUT, Channel.NAO_RPC, peer, Envelope.NO_ROBOT,
                s.call.qualifiedName(), request, payload, null));
    }

    private void readReplies() {
        while (true) {
            byte[] first = dealer.recv(ZMQ.DONTWAIT);
            if (first == null) {
                return;
            }
            List<byte[]> frames = new ArrayList<>(3);
            frames.add(first);
            while (dealer.hasReceiveMore()) {
                frames.add(dealer.recv(0));
            }
            handleReply(frames);
        }
    }

    private void handleReply(List<byte[]> frames) {
        byte[] payload = frames.get(frames.size() - 1);
        if (frames.size() != 3 || frames.get(0).length != 8 || frames.get(1).length != 0) {
            malformed(payload, "expected [8-byte id][empty][reply], got " + frames.size() + " frames");
            return;
        }
        long id = ByteBuffer.wrap(frames.get(0)).getLong();
        Pending p = pending.remove(id);
        HAWActorRPCResponse response;
        try {
            response = HAWActorRPCResponse.parseFrom(payload);
        } catch (InvalidProtocolBufferException e) {
            malformed(payload, "unreadable HAWActorRPCResponse: " + e.getMessage());
            if (p != null) {
                p.submission.future.complete(new CallOutcome.Failed("unreadable reply: " + e.getMessage()));
            }
            return;
        }
        String kind = p == null ? "stray" : p.submission.call.qualifiedName();
        envelopes.publish(new Envelope(micros(), Direction.IN, Channel.NAO_RPC, peer, Envelope.NO_ROBOT,
                kind, response, payload, null));
        if (p == null) {
            strayReplies.incrementAndGet();
            return;
        }
        replies.incrementAndGet();
        repliedSinceHandshake = true;
        disconnectsBeforeHandshake = 0;
        p.submission.future.complete(outcomeOf(response));
    }

    private CallOutcome outcomeOf(HAWActorRPCResponse response) {
        if (response.hasError()) {
            return new CallOutcome.Failed(response.getError());
        }
        if (!response.hasReturnval()) {
            return new CallOutcome.Done();
        }
        try {
            return new CallOutcome.Value(codec.decode(response.getReturnval()));
        } catch (MixedValueException e) {
            malformedReplies.incrementAndGet();
            return new CallOutcome.Failed("unreadable return value: " + e.getMessage());
        }
    }

    private void malformed(byte[] payload, String why) {
        malformedReplies.incrementAndGet();
        envelopes.publish(new Envelope(micros(), Direction.IN, Channel.NAO_RPC, peer, Envelope.NO_ROBOT,
                "malformed", null, payload, why));
    }

    private void readMonitor() {
        ZMQ.Event event;
        while (monitor != null && (event = ZMQ.Event.recv(monitor, ZMQ.DONTWAIT)) != null) {
            int e = event.getEvent();
            LOG.trace("monitor event {} {} {}", e, event.getAddress(), event.getValue());
            if (e == ZMQ.HANDSHAKE_FAILED_AUTH) {
                refused("the NAO refused our key: give it console.public — see docs/security.md");
            } else if (e == ZMQ.HANDSHAKE_FAILED_PROTOCOL || e == ZMQ.HANDSHAKE_FAILED_NO_DETAIL) {
                refused(keys != null ? NO_CURVE_HANDSHAKE
                        : "no handshake with the NAO: it runs with CURVE keys; give this console its keys (--keys)"
                          + " — see docs/security.md");
            } else if (e == ZMQ.EVENT_HANDSHAKE_PROTOCOL) {
                // JeroMQ reports the ZMTP greeting, not the end of the CURVE handshake after it.
                handshakeAtNanos = System.nanoTime();
                if (state == ConnectionState.REFUSED) {
                    probationUntilNanos = handshakeAtNanos + TimeUnit.MILLISECONDS.toNanos(CURVE_PROBATION_MS);
                } else if (state != ConnectionState.ONLINE) {
                    goOnline();
                }
            } else if (e == ZMQ.EVENT_DISCONNECTED) {
                probationUntilNanos = 0;
                if (state == ConnectionState.ONLINE) {
                    // With CURVE, a connection dropped right after the greeting without any reply is a
                    // failed CURVE handshake (a wrong server key: the robot side just closes).
                    boolean curveFailed = keys != null && !repliedSinceHandshake
                            && System.nanoTime() - handshakeAtNanos < TimeUnit.MILLISECONDS.toNanos(CURVE_PROBATION_MS)
                            && ++disconnectsBeforeHandshake >= 2;
                    goLost("disconnected (peer closed or heartbeat timed out)");
                    if (curveFailed) {
                        refused(NO_CURVE_HANDSHAKE);
                    }
                    return; // the monitor socket was replaced
                }
            }
        }
    }

    private void goOnline() {
        repliedSinceHandshake = false;
        setState(ConnectionState.ONLINE, "handshake with " + host + ":" + port);
        List<Submission> waiting = new ArrayList<>(awaitingOnline);
        awaitingOnline.clear();
        for (Submission s : waiting) {
            send(s, 1);
        }
    }

    /** A refused link whose new connection stayed up through its probation is online again. Link thread. */
    private void endProbation(long now) {
        if (state == ConnectionState.REFUSED && probationUntilNanos != 0 && now - probationUntilNanos >= 0) {
            probationUntilNanos = 0;
            disconnectsBeforeHandshake = 0;
            securityProblem = "";
            goOnline();
        }
    }

    /**
     * How long a CURVE connection must stay up after the greeting before a refused link counts
     * as online again: a failed CURVE handshake ends within a round trip, well under this.
     */
    static final long CURVE_PROBATION_MS = 1000;
    private static final String NO_CURVE_HANDSHAKE = "no CURVE handshake with the NAO: it has another key pair than "
            + "our nao-server.public, or runs without keys (then connect with --insecure) — see docs/security.md";

    /** The CURVE handshake failed: calls fail at once with the reason until a handshake succeeds. Link thread. */
    private void refused(String why) {
        securityProblem = why;
        if (state == ConnectionState.REFUSED) {
            return;
        }
        setState(ConnectionState.REFUSED, why);
        probationUntilNanos = 0;
        failAll(new CallOutcome.Lost(why));
    }

    private void goLost(String why) {
        setState(ConnectionState.LOST, why);
        failAll(new CallOutcome.Lost(why));
        // Close and reopen: whatever the old socket still held can never reach the robot.
        closeSocket();
        try {
            openSocket();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private void failAll(CallOutcome.Lost outcome) {
        for (Pending p : pending.values()) {
            lostCalls.incrementAndGet();
            p.submission.future.complete(outcome);
        }
        pending.clear();
        for (Submission s : awaitingOnline) {
            lostCalls.incrementAndGet();
            s.future.complete(outcome);
        }
        awaitingOnline.clear();
        for (Submission s : coalesced.values()) {
            lostCalls.incrementAndGet();
            s.future.complete(outcome);
        }
        coalesced.clear();
    }

    private void lose(Submission s, String why) {
        lostCalls.incrementAndGet();
        s.future.complete(new CallOutcome.Lost(why));
    }

    private void runTimers(long now) {
        endProbation(now);
        for (Iterator<Map.Entry<Long, Pending>> it = pending.entrySet().iterator(); it.hasNext(); ) {
            Pending p = it.next().getValue();
            if (now - p.attemptDeadlineNanos >= 0) {
                it.remove();
                retryOrTimeOut(p);
            }
        }
        for (Iterator<Submission> it = awaitingOnline.iterator(); it.hasNext(); ) {
            Submission s = it.next();
            if (now - s.deadlineNanos() >= 0) {
                it.remove();
                lose(s, "no connection within " + s.timeoutMillis + " ms");
            }
        }
        if (!coalesced.isEmpty()) {
            List<Submission> due = new ArrayList<>();
            for (Iterator<Submission> it = coalesced.values().iterator(); it.hasNext(); ) {
                Submission s = it.next();
                if (now - dueNanos(s) >= 0) {
                    it.remove();
                    due.add(s);
                }
            }
            for (Submission s : due) {
                if (now - s.deadlineNanos() >= 0) {
                    timeouts.incrementAndGet();
                    s.future.complete(new CallOutcome.TimedOut(s.timeoutMillis));
                } else if (state == ConnectionState.ONLINE) {
                    send(s, 1);
                } else if (state == ConnectionState.CONNECTING) {
                    awaitingOnline.add(s);
                } else {
                    lose(s, "robot not connected");
                }
            }
        }
    }

    private void retryOrTimeOut(Pending p) {
        Submission s = p.submission;
        if (s.idempotent && p.attempt <= config.retries() && state == ConnectionState.ONLINE) {
            retried.incrementAndGet();
            send(s, p.attempt + 1);
            return;
        }
        timeouts.incrementAndGet();
        long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - s.submittedNanos);
        s.future.complete(new CallOutcome.TimedOut(waited));
    }

    private void setState(ConnectionState next, String why) {
        if (state == next) {
            return;
        }
        state = next;
        String text = "nao " + host + ":" + port + " " + next.name().toLowerCase() + ": " + why;
        LOG.info(text);
        envelopes.publish(new Envelope(micros(), Direction.IN, Channel.LINK_EVENT, peer, Envelope.NO_ROBOT,
                "nao." + next.name().toLowerCase(), null, text.getBytes(StandardCharsets.UTF_8), null));
        for (Consumer<ConnectionState> l : stateListeners) {
            try {
                l.accept(next);
            } catch (RuntimeException e) {
                LOG.warn("connection state listener failed: {}", e.toString());
            }
        }
    }

    private static long micros() {
        return NaoEnvelopeChannel.nowMicros();
    }
}
