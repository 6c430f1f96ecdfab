package touchline.transport;

import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelHandler;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.channel.socket.DatagramPacket;
import io.netty.util.concurrent.ScheduledFuture;
import touchline.protocol.DatagramClass;

import java.net.InetSocketAddress;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * The reliable stream in the UDP pipeline: takes the segments of peers the console opened a
 * session with, runs their stop-and-wait machines on the event loop (retransmissions and acks
 * every 10 ms), and publishes every segment in and out as an Envelope. Segments from peers
 * without a session pass on and are reported as malformed frames by the FUmanoids decoder.
 * While the send gate holds (match mode) nothing goes out; the peer retransmits later.
 */
@ChannelHandler.Sharable
public final class ReliableStreamHandler extends ChannelInboundHandlerAdapter {

    private final Map<InetSocketAddress, ReliableSession> sessions = new ConcurrentHashMap<>();
    private final EnvelopeSink sink;
    private final MicrosClock clock;
    private volatile SendGate gate = SendGate.open();
    private volatile ChannelHandlerContext ctx;
    private ScheduledFuture<?> poller;
    private volatile SegmentAuth auth = SegmentAuth.NONE;

    /** Tags segments going out and checks those coming in (the team key; {@link #NONE} without one). */
    public interface SegmentAuth {
        SegmentAuth NONE = new SegmentAuth() {
            @Override
            public byte[] seal(InetSocketAddress peer, byte[] segment) {
                return segment;
            }

            @Override
            public void open(InetSocketAddress peer, byte[] datagram, Consumer<byte[]> then) {
                then.accept(datagram);
            }
        };

        byte[] seal(InetSocketAddress peer, byte[] segment);

        /**
         * Event loop: checks a segment and hands {@code then} the segment without its trailer, or
         * null when it is forged (dropped, counted). {@code then} may run later on another thread
         * (with a team key: the transport's publishing thread, where every robot datagram's counter
         * is checked in arrival order), never out of order with the other datagrams.
         */
        void open(InetSocketAddress peer, byte[] datagram, Consumer<byte[]> then);
    }

    public void useAuth(SegmentAuth auth) {
        this.auth = auth;
    }

    public ReliableStreamHandler(EnvelopeSink sink, MicrosClock clock) {
        this.sink = sink;
        this.clock = clock;
    }

    public void setGate(SendGate gate) {
        this.gate = gate;
    }

    /** Opens (or returns) the session with {@code peer}. */
    public ReliableSession open(InetSocketAddress peer) {
        return sessions.computeIfAbsent(peer, p -> new ReliableSession(p, d -> write(p, d), millis()));
    }

    public Optional<ReliableSession> session(InetSocketAddress peer) {
        return Optional.ofNullable(sessions.get(peer));
    }

    private long millis() {
        return clock.nowMicros() / 1000;
    }

    @Override
    public void handlerAdded(ChannelHandlerContext ctx) {
        this.ctx = ctx;
        poller = ctx.executor().scheduleAtFixedRate(this::pumpAll, 10, 10, TimeUnit.MILLISECONDS);
    }

    @Override
    public void handlerRemoved(ChannelHandlerContext ctx) {
        if (poller != null) {
            poller.cancel(false);
        }
    }

    private void pumpAll() {
        long now = millis();
        for (ReliableSession s : sessions.values()) {
            s.pump(now);
        }
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (msg instanceof ReceivedDatagram d && d.datagramClass() == DatagramClass.RELIABLE_STREAM) {
            ReliableSession s = sessions.get(d.sender());
            if (s != null) {
                auth.open(d.sender(), d.bytes(), segment -> received(d, s, segment));
                return;
            }
        }
        ctx.fireChannelRead(msg);
    }

    /** A checked segment (null: forged) is published and, unless forged, fed to its session's stream. */
    private void received(ReceivedDatagram d, ReliableSession s, byte[] segment) {
        if (segment == null) {
            sink.accept(new Envelope(d.timeMicros(), Direction.IN, Channel.RELIABLE_STREAM, d.sender(),
                    Envelope.NO_ROBOT, "forged", null, d.bytes(), "forged reliable-stream segment: dropped"));
            return;
        }
        sink.accept(new Envelope(d.timeMicros(), Direction.IN, Channel.RELIABLE_STREAM, d.sender(),
                Envelope.NO_ROBOT, segment.length == 2 ? "reliable.ack" : "reliable.data", null, d.bytes(), null));
        s.input(segment, d.timeMicros() / 1000);
    }

    private void write(InetSocketAddress peer, byte[] datagram) {
        ChannelHandlerContext c = ctx;
        if (c == null || gate.hold().isPresent()) {
            return; // held: the stop-and-wait machine retransmits once the gate opens
        }
        if (!c.executor().inEventLoop()) {
            // an ack to a segment checked on the publishing thread: tagged and written on the
            // event loop like everything else sent, so the counters leave in the order they are taken
            c.executor().execute(() -> write(peer, datagram));
            return;
        }
        byte[] wire = auth.seal(peer, datagram);
        c.writeAndFlush(new DatagramPacket(Unpooled.wrappedBuffer(wire), peer));
        sink.accept(new Envelope(clock.nowMicros(), Direction.OUT, Channel.RELIABLE_STREAM, peer, Envelope.NO_ROBOT,
                datagram.length == 2 ? "reliable.ack" : "reliable.data", null, wire, null));
    }
}
