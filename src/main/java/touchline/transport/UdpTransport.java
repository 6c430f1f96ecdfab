package touchline.transport;

import io.netty.bootstrap.Bootstrap;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.FixedRecvByteBufAllocator;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.DatagramChannel;
import io.netty.channel.socket.DatagramPacket;
import io.netty.channel.socket.nio.NioDatagramChannel;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.security.Authenticity;
import touchline.security.InboundVerifier;
import touchline.security.LinkSecurity;
import touchline.security.Trailer;

import java.net.InetSocketAddress;
import java.util.Optional;

/**
 * The console's UDP endpoint: a Netty pipeline that accounts, demultiplexes, frames and
 * decodes every datagram into the Envelope stream, and the outbound path that sends a
 * message to a robot at its current address in the framing that robot uses. Outbound
 * messages pass the {@link SendGate} (match mode) and are published as OUT Envelopes.
 */
public final class UdpTransport implements RobotCommands, AutoCloseable {

    private final UdpConfig config;
    private final MessageCodec messages;
    private final FrameCodec frames = new FrameCodec();
    private final EnvelopeSink sink;
    private final MicrosClock clock;
    private final PeerTable peers;
    private final TrafficCounters counters = new TrafficCounters();
    private volatile SendGate gate = SendGate.open();
    private final ReliableStreamHandler reliable;
    private final LinkSecurity security;
    private final InboundVerifier verifier;
    private DecodeStage stage;
    private EventLoopGroup group;
    private DatagramChannel channel;
    private volatile UdpBackend backend;
    /** What {@link CoreSplit} did at start (or why not), for the description; empty when nothing to say. */
    private volatile String cores = "";

    public UdpTransport(UdpConfig config, MessageCodec messages, EnvelopeSink sink, MicrosClock clock) {
        this(config, LinkSecurity.off(), messages, sink, clock);
    }

    /**
     * @param security the team key: with one, every datagram to a robot is tagged here (the one
     *                 send path) and every robot datagram checked before it is decoded further; the
     *                 reliable streams' segments ({@link #reliable()}) under the same key
     */
    public UdpTransport(UdpConfig config, LinkSecurity security, MessageCodec messages, EnvelopeSink sink,
                        MicrosClock clock) {
        this.security = security;
        this.verifier = security.verifier();
        this.config = config;
        this.messages = messages;
        this.sink = sink;
        this.clock = clock;
        this.peers = new PeerTable(config.robotPort());
        this.reliable = new ReliableStreamHandler(sink, clock);
        reliable.useAuth(segmentAuth());
    }

    /**
     * The reliable streams that share the robots' port (the pipeline's {@code reliable} stage,
     * before the FUmanoids decoder); with a team key their segments are tagged and checked.
     */
    public ReliableStreamHandler reliable() {
        return reliable;
    }

    public UdpTransport start() throws InterruptedException {
        // epoll + recvmmsg on Linux, NIO as the portable fallback (UdpBackend says which and why)
        backend = UdpBackend.onThisMachine(config.transport());
        // the model's work runs beside the event loop (DecodeStage); with a team key the tag and
        // counter checks too, in arrival order, the event loop decoding as without one
        stage = new DecodeStage(sink).start();
        boolean epoll = backend.epoll();
        boolean mmsg = backend.recvmmsg();
        group = new MultiThreadIoEventLoopGroup(1, epoll ? io.netty.channel.epoll.EpollIoHandler.newFactory()
                : NioIoHandler.newFactory());
        Bootstrap bootstrap = new Bootstrap()
                .group(group)
                .channel(epoll ? io.netty.channel.epoll.EpollDatagramChannel.class : NioDatagramChannel.class)
                .option(ChannelOption.SO_RCVBUF, config.receiveBuffer())
                .option(ChannelOption.SO_BROADCAST, true)
                // Read many datagrams per wake-up: a datagram never fills the buffer, so Netty's
                // "maybe more data" guess would otherwise stop after one. With recvmmsg the
                // buffer holds 32 datagrams of up to 2048 bytes (docs/benchmarks.md).
                .option(ChannelOption.RCVBUF_ALLOCATOR, new FixedRecvByteBufAllocator(mmsg ? 2048 * 32 : 2048)
                        .respectMaybeMoreData(false).maxMessagesPerRead(64))
                .handler(new ChannelInitializer<DatagramChannel>() {
                    @Override
                    protected void initChannel(DatagramChannel ch) {
                        ch.pipeline().addLast("intake", new DatagramIntake(counters, clock));
                        ch.pipeline().addLast("reliable", reliable);
                        ch.pipeline().addLast("decode", new FumanoidDecoder(frames, messages, peers, counters, sink, verifier, stage));
                    }
                });
        if (mmsg) {
            bootstrap.option(io.netty.channel.epoll.EpollChannelOption.MAX_DATAGRAM_PAYLOAD_SIZE, 2048);
        }
        try {
            channel = (DatagramChannel) bootstrap.bind(config.bindAddress(), config.listenPort()).sync().channel();
        } catch (Exception e) { // Netty throws a BindException undeclared; rethrown as it came
            if (stage != null) {
                stage.close(); // no channel, so no thread left behind for it
            }
            throw e;
        }
        splitCores();
        return this;
    }

    /** The event loop and the stage on different CPUs where the machine allows ({@link CoreSplit}). */
    private void splitCores() {
        CoreSplit.Result here = CoreSplit.forThisProcess();
        cores = here.note();
        if (here.split().isEmpty()) {
            return;
        }
        try {
            Optional<String> loopThread = channel.eventLoop().submit(CoreSplit::currentThreadId).get(5,
                    java.util.concurrent.TimeUnit.SECONDS);
            Optional<String> stageThread = stage.threadId();
            if (loopThread.isPresent() && stageThread.isPresent()) {
                cores = here.split().get().apply(loopThread.get(), stageThread.get());
            }
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            cores = "ingest threads not split across CPUs: " + e;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Tests: the stage thread's kernel id (Linux). */
    Optional<String> stageThreadId() {
        return stage.threadId();
    }

    /** Tests: the event loop's kernel id (Linux). */
    String eventLoopThreadId() throws Exception {
        return channel.eventLoop().submit(CoreSplit::currentThreadId).get().orElseThrow();
    }

    /**
     * The transport in words: the backend and why ({@link UdpBackend#describe}), and once started
     * where the two ingest threads run ({@link CoreSplit}).
     */
    public String description() {
        String c = cores;
        return backend().describe() + (c.isEmpty() ? "" : "; " + c);
    }

    /** Where the two ingest threads run, or why not as planned ({@link CoreSplit}); "" before start or with nothing to say. */
    public String cores() {
        return cores;
    }

    /**
     * Stops or resumes reading from the socket; while stopped, datagrams wait in the socket's
     * receive buffer (and beyond it are dropped by the kernel). Returns once the event loop has
     * applied it and, when stopping, once every envelope read before is published. The ingest
     * benchmark measures how fast a filled buffer is drained with this.
     */
    public void setReading(boolean on) throws InterruptedException {
        channel.eventLoop().submit(() -> channel.config().setAutoRead(on)).sync();
        if (!on && stage != null) {
            stage.awaitPublished();
        }
    }

    /** The transport this endpoint runs on and why (before {@link #start()}: what it would choose). */
    public UdpBackend backend() {
        UdpBackend b = backend;
        return b != null ? b : UdpBackend.onThisMachine(config.transport());
    }

    public int localPort() {
        return ((InetSocketAddress) channel.localAddress()).getPort();
    }

    public void setGate(SendGate gate) {
        this.gate = gate;
    }

    public PeerTable peers() {
        return peers;
    }

    public TrafficCounters counters() {
        return counters;
    }

    @Override
    public SendResult send(int robotId, Fumanoid.Message message) {
        Optional<PeerTable.Peer> peer = peers.peer(robotId);
        if (peer.isEmpty() && peers.isUntagged(robotId)) {
            return SendResult.failed("robot " + robotId + " sends untagged data: with a team key the console sends it"
                    + " nothing (give the robot the key: docs/security.md, or run the console with --insecure)");
        }
        if (peer.isEmpty()) {
            return SendResult.failed("robot " + robotId + " has not been seen yet");
        }
        return sendTo(peer.get().address(), peer.get().framing(), robotId, message);
    }

    /** Sends to an explicit address (robots not yet seen, scripts); still gated by match mode. */
    public SendResult sendTo(InetSocketAddress target, Framing framing, int robotId, Fumanoid.Message message) {
        Optional<Hold> hold = gate.hold();
        if (hold.isPresent()) {
            counters.countHeld();
            return SendResult.held(hold.get().queued());
        }
        byte[] datagram;
        try {
            datagram = frames.encode(framing, message.toByteArray());
        } catch (IllegalArgumentException e) {
            return SendResult.failed(e.getMessage());
        }
        return sendRaw(target, datagram, Channel.FUMANOID, robotId, kindOf(message), message);
    }

    /**
     * Sends bytes that are already framed; not gated here: callers gate. With a team key the
     * datagram is tagged for {@code robotId} here, so nothing reaches a robot untagged.
     *
     * <p>The tag, the write and the OUT envelope happen on the socket's event loop, never on the
     * caller's thread: a click in a view must not run the bus's subscribers (the recorder's
     * encoding, the stores) on the JavaFX thread, and tags leave in the order of their counters
     * whoever sends. "Sent" therefore means accepted: checked here (socket open, room for the tag)
     * and queued to the event loop, which writes it and then publishes it; the traffic counters
     * count it at once.
     */
    public SendResult sendRaw(InetSocketAddress target, byte[] datagram, Channel kindChannel, int robotId, String kind,
                              com.google.protobuf.Message decoded) {
        DatagramChannel ch = channel;
        if (ch == null || !ch.isActive()) {
            return SendResult.failed("the console's UDP socket is closed");
        }
        boolean tagged = security.tagger().isPresent();
        if (tagged && datagram.length + Trailer.SIZE > FrameCodec.MAX_DATAGRAM) {
            return SendResult.failed("datagram of " + datagram.length + " bytes leaves no room for its "
                    + Trailer.SIZE + "-byte tag within " + FrameCodec.MAX_DATAGRAM + " bytes");
        }
        Runnable write = () -> {
            byte[] wire = tagged ? security.tagger().get().tag(robotId, datagram) : datagram;
            ch.writeAndFlush(new DatagramPacket(Unpooled.wrappedBuffer(wire), target));
            publishOut(new Envelope(clock.nowMicros(), Direction.OUT, kindChannel, target, robotId, kind, decoded,
                    wire, null));
        };
        if (ch.eventLoop().inEventLoop()) {
            write.run();
        } else {
            try {
                ch.eventLoop().execute(write);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                return SendResult.failed("the console's UDP socket is closed");
            }
        }
        counters.countOut(datagram.length + (tagged ? Trailer.SIZE : 0));
        return SendResult.sent();
    }

    /**
     * Event loop: an envelope of what was just sent joins the received ones on the publishing
     * thread ({@link DecodeStage}), so the bus's subscribers see one stream in one order: a
     * request the model sends because of a datagram is published after that datagram, never
     * beside it on another thread (the recorder writes what it is given in this order).
     */
    private void publishOut(Envelope e) {
        DecodeStage s = stage;
        if (s == null) {
            sink.accept(e);
            return;
        }
        s.add(e);
        s.flush();
    }

    public LinkSecurity security() {
        return security;
    }

    /**
     * The reliable stream's segments under the same key: tagged for the robot last seen at the
     * peer's address on the way out, checked (and the trailer taken off) on the way in; null =
     * forged, dropped and counted. With a key the check runs on the publishing thread
     * ({@link DecodeStage}), in arrival order with the robots' datagrams whose counter it shares.
     */
    private ReliableStreamHandler.SegmentAuth segmentAuth() {
        return new ReliableStreamHandler.SegmentAuth() {
            @Override
            public byte[] seal(InetSocketAddress peer, byte[] segment) {
                return security.tagger().map(t -> t.tag(peers.robotAt(peer).orElse(0xFF), segment)).orElse(segment);
            }

            @Override
            public void open(InetSocketAddress peer, byte[] datagram, java.util.function.Consumer<byte[]> then) {
                DecodeStage s = stage;
                if (s == null || !verifier.hasKey()) {
                    then.accept(opened(peer, datagram)); // no counter to keep in order: at once
                } else {
                    s.addTask(() -> then.accept(opened(peer, datagram)));
                }
            }
        };
    }

    /** A segment's check: without its trailer, or null when forged (counted). */
    private byte[] opened(InetSocketAddress peer, byte[] datagram) {
        InboundVerifier.Result r = verifier.check(peers.robotAt(peer).orElse(0xFF), datagram);
        if (r.authenticity() == Authenticity.FORGED) {
            counters.countForged();
            return null;
        }
        return r.payloadLength() == datagram.length ? datagram : java.util.Arrays.copyOf(datagram, r.payloadLength());
    }

    private String kindOf(Fumanoid.Message message) {
        for (var field : message.getAllFields().keySet()) {
            if (field.isExtension()) {
                return field.getName();
            }
        }
        return "empty";
    }

    @Override
    public void close() {
        if (channel != null) {
            channel.close().syncUninterruptibly();
        }
        if (group != null) {
            group.shutdownGracefully(0, 1, java.util.concurrent.TimeUnit.SECONDS).syncUninterruptibly();
        }
        if (stage != null) {
            stage.close();
        }
    }
}
