package touchline.serve;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.ChannelPipeline;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.WriteBufferWaterMark;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.handler.codec.http.HttpObjectAggregator;
import io.netty.handler.codec.http.HttpServerCodec;
import io.netty.handler.codec.http.websocketx.WebSocketDecoderConfig;
import io.netty.handler.codec.http.websocketx.WebSocketFrameAggregator;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolConfig;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import io.netty.util.concurrent.ScheduledFuture;
import touchline.protocol.MessageKinds;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.net.InetSocketAddress;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The console as a live server in the Foxglove WebSocket protocol ({@code foxglove.websocket.v1},
 * and {@code foxglove.sdk.v1} for clients that ask for the newer name): Foxglove, Lichtblick
 * and scripts connect, see one channel per robot and message kind with its protobuf schema,
 * and receive what they subscribe to. Subscribe it to the Envelope stream like the recorder:
 * {@link #accept} only finds the channel and queues the message for its subscribers, never
 * waiting for a network, so viewers cannot slow the field. Read-only: nothing a viewer sends
 * reaches a robot.
 */
public final class FoxgloveServer implements EnvelopeSink, AutoCloseable {

    /** The subprotocols accepted, the spec's name first (the handshake picks the client's first match). */
    public static final String SUBPROTOCOLS = "foxglove.websocket.v1,foxglove.sdk.v1";
    static final int MAX_CHANNELS = 4096;
    /**
     * Threads writing to the viewers (each viewer stays on one): two, so eight viewers
     * subscribed to everything do not queue behind one thread's writes (docs/benchmarks.md).
     */
    static final int EVENT_LOOPS = 2;
    /**
     * Kinds whose newest message is a robot's state rather than an event: a new subscriber gets
     * it at once, so a viewer joining late (another Touchline) knows each robot's option tree
     * without asking the robot, which a read-only viewer may not.
     */
    static final java.util.Set<String> LATCHED_KINDS = java.util.Set.of("debugOptionList", "status");

    private final ServeConfig config;
    private final MicrosClock clock;
    private final ViewerTable viewers = new ViewerTable();
    private final ChannelTable channels;
    private final StandardConversion standard;
    private final GameControllerState gameController;
    private final FoxgloveFrames frames;
    private final Refusals refusals = new Refusals();
    private final Admission admission;
    private final AtomicLong badRequests = new AtomicLong();
    private volatile OptionSwitch optionSwitch; // null: viewers switch nothing
    private final AtomicLong stateFailures = new AtomicLong();
    private final AccessToken token;
    private final io.netty.handler.ssl.SslContext tls; // null: plain ws://
    private volatile EventLoopGroup group; // these three are set by start()
    private volatile Channel server;
    private volatile ScheduledFuture<?> timeTicker;
    private final java.util.List<ServedState> states = new java.util.concurrent.CopyOnWriteArrayList<>();

    /**
     * A server not yet serving: {@link #start()} binds. Throws IllegalArgumentException (a message
     * for the user) when the address is not loopback and no token is given, or the TLS files do not load.
     */
    public FoxgloveServer(ServeConfig config, MessageKinds kinds, MicrosClock clock) {
        if (!config.loopbackOnly() && (config.token() == null || config.token().isEmpty())) {
            throw new IllegalArgumentException("serving on " + config.bindAddress()
                    + " lets other machines watch: a token is required (--token, or let serve generate one)");
        }
        this.config = config;
        this.clock = clock;
        this.token = config.token() == null || config.token().isEmpty() ? null : new AccessToken(config.token());
        this.channels = new ChannelTable(kinds, viewers, MAX_CHANNELS);
        this.standard = new StandardConversion(new StandardChannels(channels));
        this.gameController = new GameControllerState(channels);
        this.frames = new FoxgloveFrames("Touchline", Long.toString(clock.nowMicros()));
        this.admission = new Admission(config.limits(), refusals);
        this.tls = config.tls() ? tlsContext(config) : null;
    }

    /**
     * Binds (starting the event loops) and starts the time ticker; once. Throws the bind's own
     * exception (e.g. a {@link java.net.BindException} for a port in use) when the port cannot be had.
     */
    public synchronized FoxgloveServer start() throws InterruptedException {
        if (group != null) {
            throw new IllegalStateException("the server was started already");
        }
        standard.start();
        EventLoopGroup loops = new MultiThreadIoEventLoopGroup(EVENT_LOOPS, NioIoHandler.newFactory());
        try {
            server = new ServerBootstrap().group(loops).channel(NioServerSocketChannel.class)
                    .childOption(ChannelOption.TCP_NODELAY, true)
                    .childOption(ChannelOption.WRITE_BUFFER_WATER_MARK, new WriteBufferWaterMark(256 * 1024, 1024 * 1024))
                    .childHandler(new ChannelInitializer<SocketChannel>() {
                        @Override
                        protected void initChannel(SocketChannel ch) {
                            if (admission.admit(ch)) {
                                pipeline(ch.pipeline());
                            }
                        }
                    })
                    .bind(new InetSocketAddress(config.bindAddress(), config.port())).sync().channel();
        } catch (Exception e) { // also the BindException Netty throws without declaring it
            loops.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            throw e;
        }
        group = loops;
        timeTicker = group.next().scheduleAtFixedRate(this::tick, config.timeEveryMillis(),
                config.timeEveryMillis(), TimeUnit.MILLISECONDS);
        return this;
    }

    /** The server's TLS context from the PEM files; IllegalArgumentException (for the user) when they do not load. */
    private static io.netty.handler.ssl.SslContext tlsContext(ServeConfig config) {
        try {
            return io.netty.handler.ssl.SslContextBuilder.forServer(config.tlsCert().toFile(), config.tlsKey().toFile())
                    .build();
        } catch (javax.net.ssl.SSLException | IllegalArgumentException e) {
            throw new IllegalArgumentException("cannot use the TLS certificate " + config.tlsCert() + " with the key "
                    + config.tlsKey() + " (PEM, key in PKCS#8 without a password): " + e.getMessage(), e);
        }
    }

    private void pipeline(ChannelPipeline p) {
        if (tls != null) {
            p.addLast(tls.newHandler(p.channel().alloc()));
        }
        p.addLast(new HttpServerCodec());
        p.addLast(new HttpObjectAggregator(8192));
        p.addLast(new OriginGate(config.origins(), refusals));
        if (token != null) {
            p.addLast(new TokenGate(token, refusals));
        }
        p.addLast(new WebSocketServerProtocolHandler(WebSocketServerProtocolConfig.newBuilder()
                .websocketPath("/").checkStartsWith(true).subprotocols(SUBPROTOCOLS)
                .handshakeTimeoutMillis(config.limits().upgradeMillis())
                .decoderConfig(WebSocketDecoderConfig.newBuilder().maxFramePayloadLength(config.maxFrameBytes())
                        .allowExtensions(false).build())
                .build()));
        p.addLast(new WebSocketFrameAggregator(config.maxFrameBytes()));
        p.addLast(new ViewerSession(channels, viewers, frames, config, refusals, admission));
        p.addLast(new ClientOps(channels, badRequests, clock, () -> optionSwitch));
    }

    @Override
    public void accept(Envelope e) {
        gameController.accept(e);
        if (e.message() != null && e.error() == null) {
            standard.offer(e);
        } else if (e.raw() == null || e.channel() == touchline.transport.Channel.LINK_EVENT) {
            return; // nothing heard to serve (a link event is the console's own, a viewer has its own)
        }
        ServedChannel c = channels.find(e);
        if (c == null) {
            return;
        }
        boolean latched = LATCHED_KINDS.contains(e.kind());
        if (c.subscribers().length == 0 && !latched) {
            return;
        }
        byte[] payload = c.payloads().payload(e);
        long timeNanos = e.timeMicros() * 1000;
        Subscription[] subscribers = latched ? c.latch(payload, timeNanos) : c.subscribers();
        for (Subscription s : subscribers) {
            s.viewer().offer(s, timeNanos, payload);
        }
    }

    /**
     * Lets tools on this machine switch the robots' options through this server ({@code
     * touchline options --connect}), by {@code to}, which passes the console's match mode; null
     * (the default): viewers switch nothing.
     */
    public void offerOptionSwitches(OptionSwitch to) {
        optionSwitch = to;
    }

    /** Serves {@code state} as its JSON channel (advertised once it has a value), e.g. the team's budget meter. */
    public void serveJson(JsonChannel state) {
        states.add(new ServedState(state, channels));
    }

    /** On the event loop, every {@link ServeConfig#timeEveryMillis()}: the server time and changed states. */
    private void tick() {
        long now = clock.nowMicros() * 1000;
        for (Viewer v : viewers.all()) {
            v.time(now);
        }
        for (ServedState s : states) {
            try {
                s.poll(now);
            } catch (RuntimeException e) {
                if (stateFailures.getAndIncrement() == 0) { // every tick would repeat it
                    org.slf4j.LoggerFactory.getLogger(FoxgloveServer.class).warn("serving a state failed: {}", e.toString());
                }
            }
        }
    }

    /** The port listened on (the one given, or the one picked for port 0). */
    public int port() {
        Channel server = this.server;
        if (server == null) {
            throw new IllegalStateException("the server is not started");
        }
        return ((InetSocketAddress) server.localAddress()).getPort();
    }

    /** The URL a viewer opens, with the token when there is one; {@code host} is what others reach this machine as. */
    public String url(String host) {
        return (tls != null ? "wss://" : "ws://") + host + ":" + port() + "/" + (config.token() == null ? "" : "?token=" + config.token());
    }

    /** The URLs viewers open: the bind address's, or one per address of this machine for a wildcard bind. */
    public java.util.List<String> urls() {
        return hosts().stream().map(this::url).toList();
    }

    private java.util.List<String> hosts() {
        java.util.List<String> hosts = new java.util.ArrayList<>();
        try {
            if (!java.net.InetAddress.getByName(config.bindAddress()).isAnyLocalAddress()) {
                return java.util.List.of(config.bindAddress());
            }
            for (java.net.NetworkInterface n : java.util.Collections.list(java.net.NetworkInterface.getNetworkInterfaces())) {
                for (java.net.InetAddress a : java.util.Collections.list(n.getInetAddresses())) {
                    if (a instanceof java.net.Inet4Address && !a.isLoopbackAddress()) {
                        hosts.add(a.getHostAddress());
                    }
                }
            }
        } catch (java.io.IOException e) { // an unresolvable bind address, or no interfaces to list
            return java.util.List.of(config.bindAddress());
        }
        return hosts.isEmpty() ? java.util.List.of("127.0.0.1") : hosts;
    }

    public ServeStats stats() {
        return new ServeStats(viewers.size(), viewers.subscriptions(), channels.size(), viewers.sent(),
                viewers.dropped(), refusals.total(), refusals.byReason(), admission.upgrading(), badRequests.get(),
                channels.refused(), standard.dropped());
    }

    /** The viewers connected now, with their subscriptions, sent and dropped counts. */
    public java.util.List<ViewerInfo> viewers() {
        return viewers.all().stream().map(Viewer::info)
                .sorted(java.util.Comparator.comparing(ViewerInfo::address)).toList();
    }

    @Override
    public synchronized void close() {
        if (group == null) { // never started: nothing to stop
            standard.close();
            return;
        }
        if (group.isShuttingDown()) {
            return;
        }
        timeTicker.cancel(false);
        standard.close();
        server.close().syncUninterruptibly();
        // say goodbye properly, so a viewer shows "closed by the server" rather than a network error
        java.util.List<io.netty.channel.ChannelFuture> goodbyes = new java.util.ArrayList<>();
        for (Viewer v : viewers.all()) {
            goodbyes.add(v.channel().writeAndFlush(new io.netty.handler.codec.http.websocketx.CloseWebSocketFrame(1001,
                    "Touchline stopped serving")).addListener(io.netty.channel.ChannelFutureListener.CLOSE));
        }
        goodbyes.forEach(f -> f.awaitUninterruptibly(500));
        group.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
    }
}
