package touchline.transport.gamecontroller;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.MonitorRequest;

import java.io.IOException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * The embedded GameController's answer to monitor applications, as the official HSL
 * GameController gives it: a host that sends "RGTr" to the request port (3636) is registered,
 * unless it sent return packets itself (a robot); registered monitors get the true game state
 * ("RGTD", also during the robots' held SET) on their game-state port with every periodic
 * datagram, and every accepted return packet forwarded to port 3940 behind the robot's IPv4
 * address. Bad requests are counted, never applied.
 */
public final class MonitorService implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(MonitorService.class);

    private final GameStateFormat trueData;
    private final int trueDataPort;
    private final int forwardPort;
    private final Consumer<String> events;
    private final MonitorRequest requests = new MonitorRequest();
    private final Set<InetAddress> monitors = ConcurrentHashMap.newKeySet();
    private final Set<InetAddress> robots = ConcurrentHashMap.newKeySet();
    private final AtomicLong badRequests = new AtomicLong();
    private final DatagramChannel out;
    private final GcListener listener;
    private int packetNumber;

    /**
     * @param requestBind  where monitor requests arrive (0.0.0.0:3636 in a game)
     * @param trueDataPort the monitors' port for true data (3838)
     * @param forwardPort  the monitors' port for forwarded return packets (3940)
     * @param trueData     the true-data format of the game's version
     * @param events       told of registrations and refusals
     */
    public MonitorService(InetSocketAddress requestBind, int trueDataPort, int forwardPort, GameStateFormat trueData,
                          Consumer<String> events) throws IOException {
        this.trueData = trueData;
        this.trueDataPort = trueDataPort;
        this.forwardPort = forwardPort;
        this.events = events;
        this.out = DatagramChannel.open();
        out.bind(new InetSocketAddress(0));
        try {
            listener = new GcListener(requestBind, this::onRequest, "gc-monitor-requests");
        } catch (IOException e) {
            out.close();
            throw e;
        }
    }

    public InetSocketAddress requestAddress() throws IOException {
        return listener.localAddress();
    }

    public Set<InetAddress> monitors() {
        return Set.copyOf(monitors);
    }

    public long badRequests() {
        return badRequests.get();
    }

    private void onRequest(byte[] data, InetSocketAddress from) {
        Decoded<MonitorRequest> d = requests.decode(data);
        InetAddress host = from.getAddress();
        if (!d.isOk()) {
            badRequests.incrementAndGet();
            events.accept("bad monitor request from " + host.getHostAddress() + ": " + d.failure() + ": "
                    + d.detail() + " (counted, not applied)");
        } else if (robots.contains(host)) {
            badRequests.incrementAndGet();
            events.accept("monitor request from " + host.getHostAddress() + " refused: it sends return packets");
        } else if (monitors.add(host)) {
            events.accept("monitor registered: " + host.getHostAddress());
        }
    }

    /** A robot's accepted return packet: its host can no longer be a monitor; monitors get a copy. */
    public void returnPacket(InetSocketAddress robot, byte[] packet) {
        robots.add(robot.getAddress());
        if (!(robot.getAddress() instanceof Inet4Address v4) || monitors.isEmpty()) {
            return;
        }
        byte[] forwarded = new byte[4 + packet.length];
        System.arraycopy(v4.getAddress(), 0, forwarded, 0, 4);
        System.arraycopy(packet, 0, forwarded, 4, packet.length);
        sendToMonitors(forwarded, forwardPort);
    }

    /** The true state, with the monitors' own packet counter (called on the sender's cycle). */
    public void publish(GameControlData truth) {
        if (monitors.isEmpty()) {
            return;
        }
        byte[] b = trueData.encode(truth.withPacketNumber(packetNumber));
        packetNumber = (packetNumber + 1) & 0xFF;
        sendToMonitors(b, trueDataPort);
    }

    private void sendToMonitors(byte[] data, int port) {
        for (InetAddress m : monitors) {
            try {
                out.send(ByteBuffer.wrap(data), new InetSocketAddress(m, port));
            } catch (IOException e) {
                LOG.warn("monitor {} not reached: {}", m.getHostAddress(), e.getMessage());
            }
        }
    }

    @Override
    public void close() {
        listener.close();
        try {
            out.close();
        } catch (IOException ignored) {
            // closing a datagram channel cannot lose data
        }
    }
}
