package touchline.app;

import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.SendGate;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.ConnectionState;
import touchline.transport.nao.NaoCall;
import touchline.transport.nao.NaoClientKeys;
import touchline.transport.nao.NaoEnvelopeChannel;
import touchline.transport.nao.NaoLink;
import touchline.transport.nao.NaoLinkConfig;
import touchline.transport.nao.NaoMoves;
import touchline.transport.nao.SequenceOutcome;
import touchline.transport.nao.WalkInput;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * One NAO driven through the application core ({@link Naos#connect}): its RPC link, its
 * high-level moves and, when a camera port is given, its camera stream, all publishing into
 * the console's Envelope stream (so the recorder and the views see the NAO's traffic; the
 * camera's frames are read from there, {@link Naos#camera()}). Every
 * call and every move passes the console's send gate first — match mode during play, and
 * "commands are off" while the console views a remote Touchline — and then ends with a
 * {@link CallOutcome} that says in words what became of it: {@link CallOutcome.HeldBack}
 * (held: nothing was sent, and nothing is sent later), a value or "done" (sent and run), or
 * an error, a timeout or a lost connection. The window's NAO view and {@code touchline nao}
 * both use this; neither builds a link of its own.
 */
public final class NaoSession implements AutoCloseable {

    private final String host;
    private final int rpcPort;
    private final NaoEnvelopeChannel channel;
    private final NaoLink link;
    private final NaoMoves moves;
    private final NaoCamera camera;
    private final Consumer<NaoSession> onClose;
    private final CompletableFuture<Void> stopped;

    /**
     * @param camPort the camera server's port, or 0 for no camera
     * @param gate    the console's gate, asked once per call
     * @param onClose told when the session closes (the console forgets it)
     */
    NaoSession(String host, int rpcPort, int camPort, NaoLinkConfig config, NaoClientKeys keys, EnvelopeSink sink,
               SendGate gate, MicrosClock clock, touchline.transport.MonotonicClock monotonic,
               Consumer<NaoSession> onClose) {
        this.host = host;
        this.rpcPort = rpcPort;
        this.onClose = onClose;
        this.channel = new NaoEnvelopeChannel(sink);
        this.link = new NaoLink(host, rpcPort, config, channel, keys, clock, monotonic).queueEveryCall();
        link.setSendGate(gate);
        this.moves = new NaoMoves(link);
        this.camera = camPort > 0 ? new NaoCamera(host, camPort, channel, keys, clock, monotonic) : null;
        this.stopped = CompletableFuture.allOf(link.stopped().toCompletableFuture(),
                camera == null ? CompletableFuture.completedFuture(null) : camera.stopped().toCompletableFuture());
    }

    /** Starts the link's thread (and the camera's): the console does, once it has made the session. */
    NaoSession start() {
        link.start();
        if (camera != null) {
            camera.start();
        }
        return this;
    }

    public String host() {
        return host;
    }

    public int rpcPort() {
        return rpcPort;
    }

    public NaoLinkConfig config() {
        return link.config();
    }

    public ConnectionState state() {
        return link.state();
    }

    /** Whether the link is encrypted (CURVE). */
    public boolean secure() {
        return link.secure();
    }

    /** Why the CURVE handshake fails, in words; "" when it does not. */
    public String securityProblem() {
        return link.securityProblem();
    }

    public NaoLink.LinkStats stats() {
        return link.stats();
    }

    /** The link's state in words, as the NAO view shows it: "online (encrypted)  3 sent, 3 replies, 0 timeouts". */
    public String describe() {
        NaoLink.LinkStats s = link.stats();
        String problem = link.securityProblem();
        return link.state().name().toLowerCase() + (link.secure() ? " (encrypted)" : " (INSECURE)") + "  " + s.sent()
                + " sent, " + s.replies() + " replies, " + s.timeouts() + " timeouts"
                + (problem.isEmpty() ? "" : " — " + problem);
    }

    /** The camera, when the session was opened with a camera port; its frames are {@link Naos#camera()}'s. */
    public Optional<NaoCamera> camera() {
        return Optional.ofNullable(camera);
    }

    /** Calls any NAOqi method with the configured timeout; held back during play. */
    public CompletableFuture<CallOutcome> call(NaoCall call) {
        return link.call(call);
    }

    /** Calls with an explicit timeout; held back during play. */
    public CompletableFuture<CallOutcome> call(NaoCall call, long timeoutMillis) {
        return link.call(call, timeoutMillis);
    }

    /** Runs the calls in order, stopping at the first that fails or is held back. */
    public CompletableFuture<SequenceOutcome> sequence(List<NaoCall> calls) {
        return link.sequence(calls);
    }

    public CompletableFuture<SequenceOutcome> stand() {
        return moves.stand();
    }

    public CompletableFuture<SequenceOutcome> sit() {
        return moves.sit();
    }

    public CompletableFuture<SequenceOutcome> turnHead(double yawRadians) {
        return moves.turnHead(yawRadians);
    }

    public CompletableFuture<CallOutcome> walk(WalkInput input) {
        return moves.walk(input);
    }

    public CompletableFuture<CallOutcome> say(String text) {
        return moves.say(text);
    }

    /**
     * Closes the camera, the link and their pipeline, and returns at once (the window's thread
     * calls it): the link's thread ends the pending calls as lost, and once it and the camera's
     * have stopped the pipeline closes and {@link #stopped()} completes.
     */
    @Override
    public void close() {
        if (camera != null) {
            camera.close();
        }
        link.close();
        stopped.thenRun(channel::close);
        onClose.accept(this);
    }

    /** Completes once the session's threads have stopped after {@link #close()}. */
    public CompletableFuture<Void> stopped() {
        return stopped.thenApply(v -> v);
    }
}
