package touchline.transport.nao;

import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.protocol.nao.MixedValueCodec;
import touchline.protocol.nao.MixedValueException;
import touchline.transport.Channel;
import touchline.transport.EnvelopeSink;
import touchline.transport.Hold;
import touchline.transport.MicrosClock;
import touchline.transport.MonotonicClock;
import touchline.transport.SendGate;

import java.net.InetSocketAddress;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The console's RPC link to one NAO's {@code HAWActorRPC} module over ZeroMQ: the facade
 * callers use. {@link #call} returns a future that always completes with a {@link CallOutcome},
 * never exceptionally. Many calls are in flight at once: each request goes out as {@code
 * [requestId][""][HAWActorRPCRequest]} and replies, which the robot's load-balancing broker
 * returns out of order, are matched by id; a reply whose id is no longer pending (it timed out)
 * is counted and dropped.
 *
 * <p>The parts, each readable and testable alone: {@link NaoConnection} (the JeroMQ DEALER and
 * its socket monitor: heartbeats, CURVE), {@link ConnectionWatch} (the connection state from the
 * monitor's events and time), {@link ReplyReader} (reply frames to request id and outcome),
 * {@link PendingCalls} (the call table: request ids, attempt deadlines, stray replies), {@link
 * CallPacing} (per-method minimum intervals, coalescing to the newest call), {@link
 * CallDispatcher} (one turn of the link: submitted calls, replies, events, timers, on an
 * injected monotonic clock), {@link LinkLoop} (the thread {@code nao-link-HOST:PORT} making the
 * turns, started by {@link #start()}, and the lock a caller sends under when it finds it free), {@link LinkTraffic} (the
 * envelopes) and {@link LinkCounters} (the {@link #stats}).
 *
 * <p>Liveness and the rules of {@link NaoLinkConfig} (timeouts, retries of idempotent methods,
 * minimum intervals): see {@link CallDispatcher}. A send gate ({@link #setSendGate}, match
 * mode) holds back every call, reads included ("during play only the GameController talks to
 * the robots"), with {@link CallOutcome.HeldBack}; nothing held back is queued for later.
 *
 * <p>Each request (OUT), reply (IN) and connection event ({@link Channel#LINK_EVENT}) is
 * published through a {@link NaoEnvelopeChannel} into the Envelope stream, stamped with the
 * wall clock handed in (the console's); deadlines run on the monotonic clock handed in.
 */
public final class NaoLink implements AutoCloseable {

    private final String host;
    private final int port;
    private final NaoLinkConfig config;
    private final NaoEnvelopeChannel envelopes;
    private final boolean ownsEnvelopes;
    private final MonotonicClock clock;
    private final MixedValueCodec codec = new MixedValueCodec();
    private final NaoConnection connection;
    private final ConnectionWatch watch;
    private final CallDispatcher dispatcher;
    private final LinkLoop loop;
    private volatile SendGate gate = SendGate.open();
    private volatile boolean callerMaySend = true;

    /**
     * A link to {@code host:port} ({@link #start()} connects) publishing into its own pipeline ending in {@code sink}.
     *
     * @param keys      CURVE client keys (the NAO link encrypted, the robot side checks our key), or null: insecure
     * @param wall      stamps the envelopes (the console's clock)
     * @param monotonic runs the calls' deadlines and pacing (the console's clock)
     */
    public NaoLink(String host, int port, NaoLinkConfig config, EnvelopeSink sink, NaoClientKeys keys,
                   MicrosClock wall, MonotonicClock monotonic) {
        this(host, port, config, new NaoEnvelopeChannel(sink), true, keys, wall, monotonic);
    }

    /** As above, publishing into a shared pipeline (e.g. with the camera stream). */
    public NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, NaoClientKeys keys,
                   MicrosClock wall, MonotonicClock monotonic) {
        this(host, port, config, envelopes, false, keys, wall, monotonic);
    }

    private NaoLink(String host, int port, NaoLinkConfig config, NaoEnvelopeChannel envelopes, boolean owns,
                    NaoClientKeys keys, MicrosClock wall, MonotonicClock monotonic) {
        this.host = host;
        this.port = port;
        this.config = config;
        this.envelopes = envelopes;
        this.ownsEnvelopes = owns;
        this.clock = monotonic;
        String peer = host + ":" + port;
        this.connection = new NaoConnection(host, port, keys);
        this.watch = new ConnectionWatch(keys != null, peer);
        LinkTraffic traffic = new LinkTraffic(envelopes, InetSocketAddress.createUnresolved(host, port), wall);
        this.dispatcher = new CallDispatcher(peer, config, connection, watch, traffic, monotonic, wall);
        this.loop = new LinkLoop(peer, connection, dispatcher, monotonic);
    }

    /** Starts the link's thread, which connects and then sends and receives. */
    public NaoLink start() {
        loop.start();
        return this;
    }

    /**
     * Every call from now on is sent by the link's thread: the caller only enqueues it (and asks
     * the send gate). For a caller that must not do the link's work, the window's thread among
     * them (sending, and publishing the request into the stream). Without it a caller that finds
     * the link idle sends at once on its own thread, a wake-up of the link thread cheaper.
     */
    public NaoLink queueEveryCall() {
        callerMaySend = false;
        return this;
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
        return dispatcher.onStateChange(listener);
    }

    /**
     * Match mode hook: while {@code mayRobotBeCommanded} is false, every call ends at once as
     * {@link CallOutcome.HeldBack} with {@code reason} and nothing is sent. Checked on the
     * caller's thread when the call is made.
     */
    public void setSendGate(BooleanSupplier mayRobotBeCommanded, Supplier<String> reason) {
        setSendGate(() -> mayRobotBeCommanded.getAsBoolean() ? Optional.empty() : Optional.of(Hold.always(reason.get())));
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
        long now = clock.nanoTime();
        CompletableFuture<CallOutcome> future = new CompletableFuture<>();
        if (!loop.running()) {
            future.complete(new CallOutcome.Lost(loop.closedBecause()));
            return future;
        }
        Optional<Hold> held = gate.hold();
        if (held.isPresent()) {
            future.complete(new CallOutcome.HeldBack(held.get().dropped()));
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
        loop.submit(new QueuedCall(call, request, timeoutMillis, config.isIdempotent(call), future, now), callerMaySend);
        return future;
    }

    /**
     * Runs the calls one after the other, each after the previous one succeeded; stops at
     * the first failure (whose outcome is the last in the result). Never completes exceptionally.
     */
    public CompletableFuture<SequenceOutcome> sequence(List<NaoCall> calls) {
        return new CallSequence(this::call).run(calls);
    }

    /** Counters since start, for the status bar and tests. */
    public LinkStats stats() {
        return dispatcher.stats();
    }

    /**
     * Counters of a link. {@code stray}: replies for calls that had already timed out;
     * {@code malformed}: replies that could not be read; {@code lost}: calls failed by a lost connection.
     */
    public record LinkStats(long sent, long replies, long timeouts, long stray, long malformed, long lost,
                            long retried) {
    }

    /**
     * Asks the link to stop and returns at once (the window's thread may call it): its thread ends
     * every open call as lost and lets go of the connection, then {@link #stopped()} completes.
     */
    @Override
    public void close() {
        if (loop.close() && ownsEnvelopes) {
            loop.stopped().thenRun(envelopes::close);
        }
    }

    /** Completes once the link's thread has stopped after {@link #close()} (its last envelopes published). */
    public java.util.concurrent.CompletionStage<Void> stopped() {
        return loop.stopped();
    }
}
