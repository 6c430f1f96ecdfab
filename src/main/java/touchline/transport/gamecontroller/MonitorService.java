package touchline.transport.gamecontroller;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.MonitorRequest;
import touchline.transport.MicrosClock;

import java.io.IOException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * The embedded GameController's answer to monitor applications, as the official HSL
 * GameController gives it: a host that sends "RGTr" to the request port (3636) is registered,
 * unless it sent return packets itself (a robot); registered monitors get the true game state
 * ("RGTD", also during the robots' held SET) on their game-state port every periodic cycle,
 * and every accepted return packet forwarded to port 3940 behind the robot's IPv4 address.
 *
 * <p>Unlike the official GameControllers, which register every requesting host for good, the
 * table holds at most {@link #MAX_MONITORS} hosts, each for {@link #LEASE_MS} after its last
 * request ({@link MonitorLeases}); requests beyond are refused and counted. The monitors'
 * datagrams are sent by this service's own thread from a bounded queue (as the official
 * GameControllers send true data apart from the robots' packet), so the robots' sender only
 * hands over and is never late for them. Bad requests are counted, never applied; events are
 * told for the first of each kind and then at every power of ten.
 */
public final class MonitorService implements AutoCloseable {

    /** The most monitors registered at once (a field has a few: TeamCommunicationMonitor, consoles). */
    public static final int MAX_MONITORS = 32;
    /** A registration lasts this long after its host's last request. */
    public static final long LEASE_MS = 60_000;
    /** Robot hosts remembered so that they cannot register (the oldest is forgotten first). */
    static final int MAX_ROBOT_HOSTS = 1024;
    /** Datagrams waiting for the monitors' thread; more are dropped and counted. */
    static final int QUEUE = 64;

    private static final Logger LOG = LoggerFactory.getLogger(MonitorService.class);

    /** One datagram for every monitor, to this port. */
    private record Outgoing(byte[] data, int port) {
    }

    private final GameStateFormat trueData;
    private final int trueDataPort;
    private final int forwardPort;
    private final Consumer<String> events;
    private final MonitorRequest requests = new MonitorRequest();
    private final MonitorLeases leases;
    private final MicrosClock clock;
    private final long leaseMs;
    private final Map<InetAddress, Boolean> robots = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<InetAddress, Boolean> eldest) {
            return size() > MAX_ROBOT_HOSTS;
        }
    };
    private final BlockingQueue<Outgoing> queue = new ArrayBlockingQueue<>(QUEUE);
    private final AtomicLong malformed = new AtomicLong();
    private final AtomicLong fromRobots = new AtomicLong();
    private final AtomicLong refusedFull = new AtomicLong();
    private final AtomicLong expired = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private final DatagramChannel out;
    private final GcListener listener;
    private Thread sender;
    private int packetNumber;
    /** The monitors' thread's last send error (logged when it changes). */
    private String lastError;

    /**
     * @param requestBind  where monitor requests arrive (0.0.0.0:3636 in a game)
     * @param trueDataPort the monitors' port for true data (3838)
     * @param forwardPort  the monitors' port for forwarded return packets (3940)
     * @param trueData     the true-data format of the game's version
     * @param events       told of registrations and refusals
     * @param clock        the console's clock: the monitors' leases
     */
    public MonitorService(InetSocketAddress requestBind, int trueDataPort, int forwardPort, GameStateFormat trueData,
                          Consumer<String> events, MicrosClock clock) throws IOException {
        this(requestBind, trueDataPort, forwardPort, trueData, events, clock, MAX_MONITORS, LEASE_MS);
    }

    /**
     * @param maxMonitors the most monitors registered at once
     * @param leaseMs     how long a registration lasts after its host's last request
     */
    public MonitorService(InetSocketAddress requestBind, int trueDataPort, int forwardPort, GameStateFormat trueData,
                          Consumer<String> events, MicrosClock clock, int maxMonitors, long leaseMs) throws IOException {
        this.clock = clock;
        this.trueData = trueData;
        this.trueDataPort = trueDataPort;
        this.forwardPort = forwardPort;
        this.events = events;
        this.leases = new MonitorLeases(maxMonitors, TimeUnit.MILLISECONDS.toMicros(leaseMs));
        this.leaseMs = leaseMs;
        this.out = DatagramChannel.open();
        out.bind(new InetSocketAddress(0));
        try {
            listener = new GcListener(requestBind, this::onRequest, "gc-monitor-requests");
        } catch (IOException e) {
            out.close();
            throw e;
        }
    }

    /** Starts the threads that hear the monitors' requests and send to the monitors. */
    public synchronized void start() {
        if (sender != null) {
            return;
        }
        listener.start();
        sender = new Thread(this::sendLoop, "gc-monitor-sender");
        sender.setDaemon(true);
        sender.start();
    }

    public InetSocketAddress requestAddress() throws IOException {
        return listener.localAddress();
    }

    public Set<InetAddress> monitors() {
        return Set.copyOf(leases.hosts());
    }

    /** Requests that did not decode or came from a robot. */
    public long badRequests() {
        return malformed.get() + fromRobots.get();
    }

    public MonitorStats stats() {
        return new MonitorStats(leases.hosts().size(), leases.capacity(), leaseMs, refusedFull.get(),
                badRequests(), expired.get(), dropped.get());
    }

    private void onRequest(byte[] data, InetSocketAddress from) {
        Decoded<MonitorRequest> d = requests.decode(data);
        InetAddress host = from.getAddress();
        if (!d.isOk()) {
            tell(malformed.incrementAndGet(), "bad monitor request from " + host.getHostAddress() + ": "
                    + d.failure() + ": " + d.detail() + " (counted, not applied)");
        } else if (isRobot(host)) {
            tell(fromRobots.incrementAndGet(), "monitor request from " + host.getHostAddress()
                    + " refused: it sends return packets");
        } else {
            switch (leases.request(host, clock.nowMicros())) {
                case REGISTERED -> events.accept("monitor registered: " + host.getHostAddress());
                case REFUSED_FULL -> tell(refusedFull.incrementAndGet(), "monitor request from "
                        + host.getHostAddress() + " refused: " + leases.capacity() + " monitors registered, the most");
                case RENEWED -> { }
            }
        }
    }

    /** The first event of a kind and then one at each power of ten, with the count so far. */
    private void tell(long count, String event) {
        if (count == 1) {
            events.accept(event);
        } else if (isPowerOfTen(count)) {
            events.accept(event + " (" + count + " so far)");
        }
    }

    private static boolean isPowerOfTen(long n) {
        long p = 1;
        while (p < n && p <= Long.MAX_VALUE / 10) {
            p *= 10;
        }
        return p == n;
    }

    private boolean isRobot(InetAddress host) {
        synchronized (robots) {
            return robots.containsKey(host);
        }
    }

    /** A robot's accepted return packet: its host can no longer be a monitor; monitors get a copy. */
    public void returnPacket(InetSocketAddress robot, byte[] packet) {
        InetAddress host = robot.getAddress();
        synchronized (robots) {
            robots.put(host, Boolean.TRUE);
        }
        if (!(host instanceof Inet4Address v4) || leases.isEmpty()) {
            return;
        }
        byte[] forwarded = new byte[4 + packet.length];
        System.arraycopy(v4.getAddress(), 0, forwarded, 0, 4);
        System.arraycopy(packet, 0, forwarded, 4, packet.length);
        hand(new Outgoing(forwarded, forwardPort));
    }

    /**
     * The true state, with the monitors' own packet counter: handed to the monitors' thread
     * (called from one thread, after the robots' periodic datagrams went out).
     */
    public void publish(GameControlData truth) {
        if (leases.isEmpty()) {
            return;
        }
        byte[] b = trueData.encode(truth.withPacketNumber(packetNumber));
        packetNumber = (packetNumber + 1) & 0xFF;
        hand(new Outgoing(b, trueDataPort));
    }

    private void hand(Outgoing datagram) {
        if (!queue.offer(datagram)) {
            dropped.incrementAndGet();
        }
    }

    private void sendLoop() {
        while (true) {
            Outgoing next;
            try {
                next = queue.take();
            } catch (InterruptedException e) {
                return;
            }
            for (InetAddress gone : leases.expire(clock.nowMicros())) {
                expired.incrementAndGet();
                events.accept("monitor " + gone.getHostAddress() + " expired: no request for " + MonitorStats.lease(leaseMs));
            }
            for (InetAddress m : leases.hosts()) {
                try {
                    out.send(ByteBuffer.wrap(next.data()), new InetSocketAddress(m, next.port()));
                } catch (java.nio.channels.ClosedChannelException e) {
                    return; // closed (or interrupted by close): the service is ending
                } catch (IOException e) {
                    String error = m.getHostAddress() + ": " + e.getMessage();
                    if (!error.equals(lastError)) {
                        lastError = error; // logged once, not every cycle for every monitor
                        LOG.warn("monitor not reached: {}", error);
                    }
                }
            }
        }
    }

    @Override
    public void close() {
        listener.close();
        Thread t;
        synchronized (this) {
            t = sender;
        }
        if (t != null) {
            t.interrupt(); // it waits for the queue, or sends on a channel closed below anyway
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        try {
            out.close();
        } catch (IOException ignored) {
            // closing a datagram channel cannot lose data
        }
    }
}
