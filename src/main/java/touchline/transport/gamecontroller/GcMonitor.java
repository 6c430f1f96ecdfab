package touchline.transport.gamecontroller;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.protocol.gamecontroller.MonitorRequest;
import touchline.protocol.gamecontroller.ReturnPacket;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * This console as a monitor of the field's HSL GameController ({@code --gc-monitor HOST}): it
 * sends the monitor request ("RGTr") to the GameController's port 3636 — at once and again
 * every {@link #REQUEST_INTERVAL_MS}, so a restarted GameController registers it again — notes
 * the registration (so the true state it then receives on 3838 is believed), and listens on
 * 3940 for the robots' return packets the GameController forwards: each robot's last packet
 * (fallen, pose, ball) and its liveness as the GameController sees it. Forwarded packets are
 * believed only from the monitored GameController's address; the others, and those that do not
 * decode (a bad address prefix, a bad return packet), are counted with their reason, per
 * source up to {@link BadPackets#MAX_SOURCES} and together beyond.
 * The official GameController refuses a host that itself sent return packets as a monitor.
 * Its port is bound when made; it requests and listens from {@link #start()}.
 */
public final class GcMonitor implements AutoCloseable {

    public static final long REQUEST_INTERVAL_MS = 2000;

    private static final Logger LOG = LoggerFactory.getLogger(GcMonitor.class);

    /**
     * A robot's last return packet as forwarded by the GameController.
     *
     * @param robotHost the robot's address as the GameController saw it
     * @param packet    what the robot sent
     * @param atMs      when it arrived here
     */
    public record Seen(String robotHost, ReturnPacket.V4 packet, long atMs) {
    }

    private final InetSocketAddress gameController;
    private final EnvelopeSink sink;
    private final touchline.transport.MicrosClock clock;
    private final DatagramChannel requests;
    private final GcListener forwarded;
    private final ScheduledExecutorService ticker;
    private final ForwardedReturnPacket.Decoder decoder = new ForwardedReturnPacket.Decoder();
    private final byte[] request = new MonitorRequest().encode();
    private final RobotLiveness liveness = new RobotLiveness();
    private final BadPackets badPackets = new BadPackets();
    private final Map<RobotLiveness.RobotKey, Seen> lastSeen = new ConcurrentHashMap<>();
    private boolean started;

    /**
     * @param gameController the GameController's monitor-request address (HOST:3636)
     * @param forwardBind    where forwarded return packets arrive (0.0.0.0:3940)
     * @param registrations  told that this GameController's true data is now expected
     * @param sink           receives the forwarded packets as GAMECONTROLLER envelopes
     * @param clock          the console's clock: envelope stamps and liveness
     */
    public GcMonitor(InetSocketAddress gameController, InetSocketAddress forwardBind,
                     MonitorRegistrations registrations, EnvelopeSink sink, touchline.transport.MicrosClock clock)
            throws IOException {
        this.gameController = gameController;
        this.sink = sink;
        this.clock = clock;
        registrations.requested(gameController.getAddress());
        requests = DatagramChannel.open();
        try {
            forwarded = new GcListener(forwardBind, this::onForwarded, "gc-monitor");
        } catch (IOException e) {
            requests.close();
            throw e;
        }
        ticker = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "gc-monitor-request");
            t.setDaemon(true);
            return t;
        });
    }

    /** Starts monitoring: the first request at once, then every {@link #REQUEST_INTERVAL_MS}; returns this. */
    public synchronized GcMonitor start() {
        if (!started) {
            started = true;
            forwarded.start();
            ticker.scheduleAtFixedRate(this::sendRequest, 0, REQUEST_INTERVAL_MS, TimeUnit.MILLISECONDS);
        }
        return this;
    }

    private void sendRequest() {
        try {
            requests.send(ByteBuffer.wrap(request), gameController);
            sink.accept(new Envelope(clock.nowMicros(), Direction.OUT, Channel.GAMECONTROLLER, gameController,
                    Envelope.NO_ROBOT, "gc.monitor.request", null, request, null));
        } catch (IOException e) {
            // the field network may come and go; the next request follows in REQUEST_INTERVAL_MS
            LOG.warn("monitor request to {}: {}", gameController, e.toString());
        }
    }

    private void onForwarded(byte[] data, InetSocketAddress from) {
        Decoded<ForwardedReturnPacket> d = decoder.decode(data);
        String reason = !from.getAddress().equals(gameController.getAddress())
                ? "not from the monitored GameController " + gameController.getAddress().getHostAddress()
                : d.isOk() ? null : d.failure() + ": " + d.detail();
        if (reason != null) {
            badPackets.count(from, reason);
            sink.accept(new Envelope(clock.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                    "gc.return.forwarded", null, data, reason));
            return;
        }
        ReturnPacket.V4 p = d.value().packet();
        long now = clock.nowMicros() / 1000;
        liveness.heard(p.team(), p.player(), now);
        lastSeen.put(new RobotLiveness.RobotKey(p.team(), p.player()), new Seen(d.value().robotHost(), p, now));
        sink.accept(new Envelope(clock.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                "gc.return.forwarded", null, data, null));
    }

    public InetSocketAddress forwardAddress() throws IOException {
        return forwarded.localAddress();
    }

    /** Liveness of each robot by the return packets the GameController forwarded. */
    public RobotLiveness liveness() {
        return liveness;
    }

    /** Each robot's last forwarded return packet, by team and player. */
    public Map<RobotLiveness.RobotKey, Seen> robots() {
        return new TreeMap<>(lastSeen);
    }

    /**
     * Each robot as the GameController sees it, one line a robot ("5/2 10.0.0.12 GOOD upright
     * pose (...) ball ..."), then one line per source of bad forwarded packets: for the
     * {@code listen} command and the window's "GameController's robots" view alike.
     */
    public java.util.List<String> describe(long nowMs) {
        java.util.List<String> lines = new java.util.ArrayList<>();
        robots().forEach((key, seen) -> {
            ReturnPacket.V4 p = seen.packet();
            lines.add(String.format(java.util.Locale.ROOT, "%-6s %-15s %-7s %s pose (%.0f, %.0f, %.2f) ball %s", key,
                    seen.robotHost(), liveness.status(key.team(), key.player(), nowMs),
                    p.fallen() == 1 ? "FALLEN " : "upright", p.poseX(), p.poseY(), p.poseTheta(),
                    p.ballAge() < 0 ? "never seen" : String.format(java.util.Locale.ROOT, "(%.0f, %.0f) %.1f s ago",
                            p.ballX(), p.ballY(), p.ballAge())));
        });
        badPackets.bySource().forEach((src, t) ->
                lines.add("bad forwarded packets from " + src + ": " + t.count() + " (last: " + t.lastReason() + ")"));
        return lines;
    }

    /** Forwarded datagrams that did not decode, per source with the last reason. */
    public BadPackets badPackets() {
        return badPackets;
    }

    @Override
    public void close() {
        ticker.shutdownNow();
        forwarded.close();
        try {
            requests.close();
        } catch (IOException ignored) {
            // nothing to flush on a datagram socket
        }
    }
}
