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
    static final int UPGRADE_SECONDS = 10;

    private final ServeConfig config;
    private final MicrosClock clock;
    private final ViewerTable viewers = new ViewerTable();
    private final ChannelTable channels;
    private final StandardChannels standard;
    private final GameControllerState gameController;
    private final FoxgloveFrames frames;
    private final AtomicLong refused = new AtomicLong();
    private final AtomicLong badRequests = new AtomicLong();
    private final AtomicLong stateFailures = new AtomicLong();
    private final AccessToken token;
    private final EventLoopGroup group;
    private final Channel server;
    private final ScheduledFuture<?> timeTicker;
    private final java.util.List<ServedState> states = new java.util.concurrent.CopyOnWriteArrayList<>();

    /**
     * Binds and starts serving. Throws IllegalArgumentException (a message for the user) when
     * the address is not loopback and no token is given, and the bind's own exception (e.g. a
     * {@link java.net.BindException} for a port in use) when the port cannot be had.
     */
    public FoxgloveServer(ServeConfig config, MessageKinds kinds, MicrosClock clock) throws InterruptedException {
        if (!config.loopbackOnly() && (config.token() == null || config.token().isEmpty())) {
            throw new IllegalArgumentException("serving on " + config.bindAddress()
                    + " lets other machines watch: a token is required (--token, or let serve generate one)");
        }
        this.config = config;
        this.clock = clock;
        this.token = config.token() == null || config.token().isEmpty() ? null : new AccessToken(config.token());
        this.channels = new ChannelTable(kinds, viewers, MAX_CHANNELS);
        this.standard = new StandardChannels(channels);
        this.gameController = new GameControllerState(channels);
        this.frames = new FoxgloveFrames("Touchline", Long.toString(clock.nowMicros()));
        this.group = new MultiThreadIoEventLoopGroup(1, NioIoHandler.newFactory());
        try {
            this.server = new ServerBootstrap().group(group).channel(NioServerSocketChannel.class)
                    .childOption(ChannelOption.TCP_NODELAY, true)
                    .childOption(ChannelOption.WRITE_BUFFER_WATER_MARK, new WriteBufferWaterMark(256 * 1024, 1024 * 1024))
                    .childHandler(new ChannelInitializer<SocketChannel>() {
                        @Override
                        protected void initChannel(SocketChannel ch) {
                            pipeline(ch.pipeline());
                        }
                    })
                    .bind(new InetSocketAddress(config.bindAddress(), config.port())).sync().channel();
        } catch (Exception e) { // also the BindException Netty throws without declaring it
            group.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            throw e;
        }
        this.timeTicker = group.next().scheduleAtFixedRate(this::tick, config.timeEveryMillis(),
                config.timeEveryMillis(), TimeUnit.MILLISECONDS);
    }

    private void pipeline(ChannelPipeline p) {
        // a connection that never completes its upgrade is closed (ViewerSession removes this once it has)
        p.addLast(ViewerSession.UPGRADE_TIMEOUT, new io.netty.handler.timeout.ReadTimeoutHandler(UPGRADE_SECONDS));
        p.addLast(new HttpServerCodec());
        p.addLast(new HttpObjectAggregator(8192));
        if (token != null) {
            p.addLast(new TokenGate(token, refused));
        }
        p.addLast(new WebSocketServerProtocolHandler(WebSocketServerProtocolConfig.newBuilder()
                .websocketPath("/").checkStartsWith(true).subprotocols(SUBPROTOCOLS)
                .handshakeTimeoutMillis(10_000)
                .decoderConfig(WebSocketDecoderConfig.newBuilder().maxFramePayloadLength(config.maxFrameBytes())
                        .allowExtensions(false).build())
                .build()));
        p.addLast(new WebSocketFrameAggregator(config.maxFrameBytes()));
        p.addLast(new ViewerSession(channels, viewers, frames, config, refused));
        p.addLast(new ClientOps(channels, badRequests, clock));
    }

    @Override
    public void accept(Envelope e) {
        gameController.accept(e);
        if (e.message() == null || e.error() != null) {
            return;
        }
        standard.accept(e);
        ServedChannel c = channels.find(e);
        if (c == null) {
            return;
        }
        Subscription[] subscribers = c.subscribers();
        if (subscribers.length == 0) {
            return;
        }
        byte[] payload = c.payloads().payload(e);
        long timeNanos = e.timeMicros() * 1000;
        for (Subscription s : subscribers) {
            s.viewer().offer(s, timeNanos, payload);
        }
    }

    /** Serves match mode as the JSON channel {@code /touchline/matchMode}. */
    public void serveMatchMode(touchline.game.MatchMode matchMode) {
        states.add(new ServedState(new MatchModeState(matchMode), channels));
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
        return ((InetSocketAddress) server.localAddress()).getPort();
    }

    /** The URL a viewer opens, with the token when there is one; {@code host} is what others reach this machine as. */
    public String url(String host) {
        return "ws://" + host + ":" + port() + "/" + (config.token() == null ? "" : "?token=" + config.token());
    }

    public ServeStats stats() {
        return new ServeStats(viewers.size(), viewers.subscriptions(), channels.size(), viewers.sent(),
                viewers.dropped(), refused.get(), badRequests.get(), channels.refused());
    }

    @Override
    public void close() {
        timeTicker.cancel(false);
        server.close().syncUninterruptibly();
        group.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
    }
}
