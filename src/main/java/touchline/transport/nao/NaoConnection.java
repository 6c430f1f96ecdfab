package touchline.transport.nao;

import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The JeroMQ side of one NAO link: a DEALER to the robot's RPC module and the PAIR reading its
 * socket monitor, in their own context. Liveness is ZeroMQ's: {@code setImmediate(false)} (in
 * JeroMQ this is libzmq's ZMQ_IMMEDIATE=1: queue only on completed connections, so nothing
 * waits in a pipe for a dead robot), ZMTP heartbeats (500 ms interval, 1500 ms timeout) and a
 * 2 s handshake interval; CURVE with the client keys unless insecure. ZeroMQ sockets are not
 * thread-safe: the link calls this only under its lock. {@link #reopen} closes the sockets and
 * opens new ones, so whatever the old ones still held can never reach the robot.
 */
final class NaoConnection implements LinkWire {

    static final int HEARTBEAT_IVL_MS = 500;
    static final int HEARTBEAT_TIMEOUT_MS = 1500;
    static final int HEARTBEAT_TTL_MS = 3000;
    static final int HANDSHAKE_IVL_MS = 2000;
    private static final AtomicLong MONITOR_IDS = new AtomicLong();

    /** What the socket monitor saw, in the link's terms. */
    enum Event {
        /** The robot's ZAP handler refused our key. */
        KEY_REFUSED,
        /** The ZMTP or CURVE handshake failed (wrong mechanism or keys). */
        NO_HANDSHAKE,
        /** The ZMTP greeting went through (JeroMQ reports it before the end of a CURVE handshake). */
        GREETING,
        /** The connection closed (peer closed, heartbeat timed out). */
        DISCONNECTED,
        /** Anything else (connect attempts, retries). */
        OTHER
    }

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(NaoConnection.class);

    private final String host;
    private final int port;
    private final NaoClientKeys keys;
    private final ZContext zmq = new ZContext(1);
    private ZMQ.Socket dealer;
    private ZMQ.Socket monitor;
    private boolean replaced;
    private SelectionKey dealerKey;
    private SelectionKey monitorKey;

    NaoConnection(String host, int port, NaoClientKeys keys) {
        this.host = host;
        this.port = port;
        this.keys = keys;
    }

    boolean secure() {
        return keys != null;
    }

    boolean isOpen() {
        return dealer != null;
    }

    void open() {
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
        replaced = true;
    }

    void close() {
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

    /** Closes the sockets and opens new ones. */
    @Override
    public void reopen() {
        close();
        open();
    }

    /** Closes the sockets and the context: the end of the link. */
    void shutdown() {
        close();
        zmq.close();
    }

    /**
     * Sends {@code [id][""][payload]} without waiting; false when there is no completed
     * connection to send on (nothing was queued then).
     */
    @Override
    public boolean send(long id, byte[] payload) {
        byte[] idBytes = ByteBuffer.allocate(8).putLong(id).array();
        try {
            return dealer.send(idBytes, ZMQ.SNDMORE | ZMQ.DONTWAIT)
                    && dealer.send(new byte[0], ZMQ.SNDMORE | ZMQ.DONTWAIT)
                    && dealer.send(payload, ZMQ.DONTWAIT);
        } catch (RuntimeException | AssertionError e) {
            // A connection dropped between two frames of one message: JeroMQ's load balancer
            // asserts (LB.sendpipe "!more", an AssertionError under -ea) and would otherwise
            // send the next frame as the rest of this message. New sockets, nothing half-sent.
            LOG.warn("NAO {}:{}: send failed mid-message ({}); reopening the connection", host, port, e.toString());
            reopen();
            return false;
        }
    }

    /** The frames of the next reply, or null when none is waiting. */
    @Override
    public List<byte[]> receive() {
        byte[] first = dealer.recv(ZMQ.DONTWAIT);
        if (first == null) {
            return null;
        }
        List<byte[]> frames = new ArrayList<>(3);
        frames.add(first);
        while (dealer.hasReceiveMore()) {
            frames.add(dealer.recv(0));
        }
        return frames;
    }

    /**
     * Whether a reply is waiting. ZMQ_FD contract: a send may consume the mailbox signal of a
     * reply that arrived meanwhile, and a selector would then not wake for it.
     */
    boolean replyWaiting() {
        return dealer != null && (dealer.getEvents() & ZMQ.Poller.POLLIN) != 0;
    }

    /** The next monitor event, or null when none is waiting. */
    @Override
    public Event nextEvent() {
        ZMQ.Event event = monitor == null ? null : ZMQ.Event.recv(monitor, ZMQ.DONTWAIT);
        if (event == null) {
            return null;
        }
        int e = event.getEvent();
        LOG.trace("monitor event {} {} {}", e, event.getAddress(), event.getValue());
        if (e == ZMQ.HANDSHAKE_FAILED_AUTH) {
            return Event.KEY_REFUSED;
        }
        if (e == ZMQ.HANDSHAKE_FAILED_PROTOCOL || e == ZMQ.HANDSHAKE_FAILED_NO_DETAIL) {
            return Event.NO_HANDSHAKE;
        }
        if (e == ZMQ.EVENT_HANDSHAKE_PROTOCOL) {
            return Event.GREETING;
        }
        return e == ZMQ.EVENT_DISCONNECTED ? Event.DISCONNECTED : Event.OTHER;
    }

    /** (Re)registers the sockets' signalling descriptors with {@code selector} after they were (re)opened. */
    void registerIfReplaced(Selector selector) throws IOException {
        if (!replaced) {
            return;
        }
        // A replaced socket's descriptor is closed later, by JeroMQ's reaper thread: drop our
        // keys now rather than select on a dying descriptor until then.
        if (dealerKey != null) {
            dealerKey.cancel();
            monitorKey.cancel();
        }
        dealerKey = dealer.getFD().register(selector, SelectionKey.OP_READ);
        monitorKey = monitor.getFD().register(selector, SelectionKey.OP_READ);
        replaced = false;
    }
}
