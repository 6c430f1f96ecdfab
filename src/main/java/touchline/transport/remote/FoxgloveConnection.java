package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONObject;
import touchline.transport.EnvelopeSink;

import javax.net.ssl.SSLContext;
import java.net.URI;
import java.net.http.HttpClient;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The connection and protocol core both Foxglove WebSocket clients ride on — the remote viewer
 * of another Touchline ({@link RemoteStream}) and a ROS 2 robot's bridge ({@link Bridge}):
 * connects to the server ({@code ws://} or {@code wss://}) offering both subprotocols,
 * subscribes to each channel {@code reader} wants, hands each message's envelope to
 * {@code sink} and the ops it does not handle itself to {@code replies}. A lost or refused
 * connection is a status, never an exception: it reconnects by itself, waiting twice as long
 * each time up to {@code maxBackoff}, and subscribes afresh. One connection at a time is a
 * {@link FoxgloveSession}.
 */
final class FoxgloveConnection implements AutoCloseable {

    static final String SUBPROTOCOL = "foxglove.websocket.v1";
    /**
     * What this client offers: the Foxglove SDK's servers (and the {@code foxglove_bridge} built on
     * it) accept only {@code foxglove.sdk.v1}, older ones only {@code foxglove.websocket.v1}; the
     * server picks one, and the two carry the same ops.
     */
    static final String[] SUBPROTOCOLS = {"foxglove.sdk.v1", SUBPROTOCOL};
    static final Duration FIRST_BACKOFF = Duration.ofMillis(250);
    /** The largest message taken from a server: more than a raw camera frame; anything bigger is dropped unread. */
    static final int MAX_MESSAGE_BYTES = 16 << 20;
    /** The most channels read from one connection's advertises (a robot has tens; a hostile server may claim millions). */
    static final int MAX_CHANNELS = 4096;
    /** A Touchline server sends its time ten times a second; this long without a word, the connection is dead. */
    static final Duration SILENCE = Duration.ofSeconds(15);
    static final Duration HANDSHAKE = Duration.ofSeconds(5);

    private final URI uri;
    private final String shownUrl;
    private final SSLContext tls;
    final EnvelopeSink sink;
    final ChannelReader reader;
    final ServerReplies replies;
    final int maxMessageBytes;
    final Duration silence;
    private final Duration handshake;
    private final Duration maxBackoff;
    final ScheduledExecutorService reconnects;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong unusable = new AtomicLong();
    private final AtomicLong losses = new AtomicLong();
    private volatile String problem = "";
    private volatile RemoteStatus.State state = RemoteStatus.State.CONNECTING;
    private volatile String detail = "";
    private volatile FoxgloveSession session;
    private volatile boolean closed;
    private volatile JSONObject serverInfo = new JSONObject();
    private volatile String subprotocol = "";
    private Duration backoff = FIRST_BACKOFF;

    /**
     * @param reader   makes each advertised channel it wants into a {@link StreamChannel}
     * @param replies  hears the ops and binary replies the core does not handle (parameter values, services, answers)
     * @param silence  this long without a word from the server, the connection is dropped and made again
     */
    FoxgloveConnection(URI uri, SSLContext tls, ChannelReader reader, ServerReplies replies, EnvelopeSink sink,
                       Duration maxBackoff, int maxMessageBytes, Duration silence, Duration handshake) {
        String scheme = uri.getScheme() == null ? "" : uri.getScheme().toLowerCase(Locale.ROOT);
        if (!scheme.equals("ws") && !scheme.equals("wss")) {
            throw new IllegalArgumentException("not a WebSocket URL (ws://HOST:PORT/?token=… or wss://…): " + uri);
        }
        this.uri = uri;
        this.shownUrl = scheme + "://" + uri.getHost() + (uri.getPort() < 0 ? "" : ":" + uri.getPort()) + "/";
        this.maxMessageBytes = maxMessageBytes;
        this.silence = silence;
        this.handshake = handshake;
        this.tls = tls;
        this.reader = reader;
        this.replies = replies;
        this.sink = sink;
        this.maxBackoff = maxBackoff;
        this.reconnects = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "touchline-remote");
            t.setDaemon(true);
            return t;
        });
    }

    /** Starts connecting; returns at once (the status says how it goes). */
    void start() {
        reconnects.execute(this::connect);
    }

    /** The server's address without its token. */
    String shownUrl() {
        return shownUrl;
    }

    RemoteStatus status() {
        FoxgloveSession s = session;
        return new RemoteStatus(state, shownUrl, detail, s == null ? 0 : s.channels(), received.get(), unusable.get(),
                problem);
    }

    private void connect() {
        if (closed) {
            return;
        }
        state = RemoteStatus.State.CONNECTING;
        FoxgloveSession s = new FoxgloveSession(this);
        // a client per connection: the JDK's can break for good on a server that cuts a frame
        // short (an InternalError on its own threads), and must not take the next attempts with it
        HttpClient.Builder b = HttpClient.newBuilder().connectTimeout(handshake);
        if (tls != null) {
            b.sslContext(tls);
        }
        b.build().newWebSocketBuilder().subprotocols(SUBPROTOCOLS[0], SUBPROTOCOLS[1]).connectTimeout(handshake)
                .buildAsync(uri, s).whenComplete((ws, failure) -> {
                    if (failure != null) {
                        s.lost(reason(failure));
                    }
                });
    }

    static String reason(Throwable t) {
        Throwable c = t instanceof java.util.concurrent.CompletionException && t.getCause() != null ? t.getCause() : t;
        if (c instanceof java.net.http.WebSocketHandshakeException h) {
            int code = h.getResponse().statusCode();
            return "refused: HTTP " + code + (code == 401 || code == 403 ? " (wrong or missing token?)" : "");
        }
        if (c instanceof java.net.ConnectException) {
            return "nobody listening";
        }
        if (c instanceof java.net.http.HttpTimeoutException) {
            return "no answer to the WebSocket handshake";
        }
        if (c instanceof InternalError || c instanceof java.io.EOFException) {
            return "the connection broke off in the middle of a message";
        }
        if (c instanceof javax.net.ssl.SSLException) {
            return "TLS: " + c.getMessage();
        }
        return c.getMessage() == null ? c.getClass().getSimpleName() : c.getMessage();
    }

    synchronized void retryLater(String why) {
        if (closed) {
            return;
        }
        state = RemoteStatus.State.LOST;
        detail = why;
        losses.incrementAndGet();
        long wait = backoff.toMillis();
        backoff = backoff.multipliedBy(2).compareTo(maxBackoff) > 0 ? maxBackoff : backoff.multipliedBy(2);
        reconnects.schedule(this::connect, wait, TimeUnit.MILLISECONDS);
    }

    synchronized void connected(FoxgloveSession s) {
        session = s;
        state = RemoteStatus.State.CONNECTED;
        detail = "";
        subprotocol = s.socket == null || s.socket.getSubprotocol() == null ? "" : s.socket.getSubprotocol();
        s.watch();
    }

    /** Something from the server could not be used: counted, and the newest one said in the status. */
    void unusable(String what) {
        unusable.incrementAndGet();
        problem = what;
    }

    /** One envelope rebuilt and handed on. */
    void received() {
        received.incrementAndGet();
    }

    /** The server's last status message without an answer's id (said in the status). */
    void said(String message) {
        detail = message;
    }

    void serverInfo(JSONObject info) {
        serverInfo = info;
    }

    /** The server advertised its channels: it really serves us (one that only says "too many viewers" does not). */
    synchronized void welcomed() {
        backoff = FIRST_BACKOFF;
    }

    /** The server's name as its serverInfo says it; "" before the first one. */
    String serverName() {
        return serverInfo.optString("name", "");
    }

    /** What the server's serverInfo said of itself ({@code supportedEncodings}, {@code capabilities}…); empty before one. */
    JSONObject serverInfo() {
        return serverInfo;
    }

    /** Whether the server said it offers {@code capability} (e.g. {@code parameters}, {@code clientPublish}). */
    boolean offers(String capability) {
        JSONArray caps = serverInfo.optJSONArray("capabilities");
        for (int i = 0; caps != null && i < caps.length(); i++) {
            if (capability.equals(caps.optString(i))) {
                return true;
            }
        }
        return false;
    }

    /** The subprotocol the server chose on the current (or last) connection; "" before one. */
    String subprotocol() {
        return subprotocol;
    }

    /** Connections lost since the start (each followed by a reconnection attempt after the backoff). */
    long losses() {
        return losses.get();
    }

    /** Sends one JSON op on the current connection; false when there is none. */
    boolean sendText(String op) {
        FoxgloveSession s = session;
        return s != null && s.sendText(op);
    }

    /** Sends one binary message on the current connection; false when there is none. */
    boolean sendBinary(byte[] message) {
        FoxgloveSession s = session;
        return s != null && s.sendBinary(message);
    }

    @Override
    public void close() {
        closed = true;
        reconnects.shutdownNow();
        FoxgloveSession s = session;
        if (s != null) {
            s.abort();
        }
    }
}
