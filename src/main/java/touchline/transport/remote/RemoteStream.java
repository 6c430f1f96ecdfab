package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;
import touchline.protocol.FrameCodec;
import touchline.protocol.MessageCodec;
import touchline.transport.EnvelopeSink;

import javax.net.ssl.SSLContext;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Another Touchline's live stream as envelopes: connects to its Foxglove WebSocket server
 * ({@code ws://} or {@code wss://}, with the token in the URL), subscribes to every robot
 * channel it advertises (now and later), rebuilds each message into the envelope the remote
 * console saw and hands it to {@code sink}. A lost or refused connection is a status, never an
 * exception: it reconnects by itself, waiting twice as long each time up to {@code maxBackoff},
 * and subscribes afresh. Read-only, like the server: it sends nothing but subscriptions.
 */
public final class RemoteStream implements AutoCloseable {

    public static final String SUBPROTOCOL = "foxglove.websocket.v1";
    /**
     * What this client offers: the Foxglove SDK's servers (and the {@code foxglove_bridge} built on
     * it) accept only {@code foxglove.sdk.v1}, older ones only {@code foxglove.websocket.v1}; the
     * server picks one, and the two carry the same ops.
     */
    public static final String[] SUBPROTOCOLS = {"foxglove.sdk.v1", SUBPROTOCOL};
    /** The query by which a Touchline server also advertises its channels of bytes (serve.Viewer's parameter). */
    static final String BYTES_QUERY = "raw=1";
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
    private final EnvelopeSink sink;
    private final ChannelReader reader;
    private final ServerReplies replies;
    private final Duration maxBackoff;
    private final ScheduledExecutorService reconnects;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong unusable = new AtomicLong();
    private final int maxMessageBytes;
    private final Duration silence;
    private final Duration handshake;
    private volatile String problem = "";
    private volatile RemoteStatus.State state = RemoteStatus.State.CONNECTING;
    private volatile String detail = "";
    private volatile Session session;
    private final AtomicLong requests = new AtomicLong();
    private final Map<String, java.util.concurrent.CompletableFuture<touchline.transport.SendResult>> answers =
            new ConcurrentHashMap<>();
    private volatile boolean closed;
    private Duration backoff = FIRST_BACKOFF;
    private final AtomicLong losses = new AtomicLong();
    private volatile JSONObject serverInfo = new JSONObject();
    private volatile String subprotocol = "";

    /**
     * @param uri        e.g. {@code ws://10.0.0.5:8765/?token=…}
     * @param tls        trust for {@code wss://} (see {@link RemoteTrust}), or null for the JDK's default
     * @param codec      decodes the rebuilt FUmanoids messages (its kinds name the extensions, a team's included)
     * @param sink       where the envelopes go (the console's Envelope stream)
     * @param maxBackoff the longest wait between reconnection attempts
     */
    public RemoteStream(URI uri, SSLContext tls, MessageCodec codec, EnvelopeSink sink, Duration maxBackoff) {
        this(uri, tls, codec, sink, maxBackoff, MAX_MESSAGE_BYTES, SILENCE, HANDSHAKE);
    }

    /** As above, with the limits a test can make small: the largest message, the longest silence and handshake. */
    RemoteStream(URI uri, SSLContext tls, MessageCodec codec, EnvelopeSink sink, Duration maxBackoff,
                 int maxMessageBytes, Duration silence, Duration handshake) {
        this(withBytesQuery(uri), tls, touchlineChannels(codec), ServerReplies.NONE, sink, maxBackoff, maxMessageBytes,
                silence, handshake);
    }

    /**
     * Any Foxglove WebSocket server's stream: {@code reader} makes each advertised channel it
     * wants into a {@link StreamChannel}, {@code replies} hears the ops and binary replies this
     * stream does not handle itself (parameter values, services, their answers).
     */
    RemoteStream(URI uri, SSLContext tls, ChannelReader reader, ServerReplies replies, EnvelopeSink sink,
                 Duration maxBackoff, int maxMessageBytes, Duration silence, Duration handshake) {
        String scheme = uri.getScheme() == null ? "" : uri.getScheme().toLowerCase(java.util.Locale.ROOT);
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

    /**
     * Asks for the channels of bytes too (GameController packets, malformed datagrams), which a
     * Touchline server advertises only to viewers that ask: Foxglove has no schema for them.
     */
    private static URI withBytesQuery(URI uri) {
        String u = uri.toString();
        int hash = u.indexOf('#');
        u = hash < 0 ? u : u.substring(0, hash);
        return URI.create(u + (uri.getRawQuery() == null ? "?" : "&") + BYTES_QUERY);
    }

    /** A Touchline's robot channels, rebuilt into the envelopes it saw; its JSON state channels are skipped. */
    private static ChannelReader touchlineChannels(MessageCodec codec) {
        FrameCodec frames = new FrameCodec(Integer.MAX_VALUE);
        return advertised -> {
            if (advertised.optJSONObject("metadata") == null) {
                return null; // a JSON state channel, or not a Touchline's
            }
            try {
                return RemoteChannel.of(advertised, codec, frames);
            } catch (IllegalArgumentException e) {
                if ("no Touchline metadata".equals(e.getMessage())) {
                    return null;
                }
                throw e;
            }
        };
    }

    /** Starts connecting; returns at once (the status says how it goes). */
    public RemoteStream start() {
        reconnects.execute(this::connect);
        return this;
    }

    /**
     * Asks the serving console to switch robot {@code robotId}'s {@code option} on or off (a
     * Touchline server offers it to tools on its own machine); completes with the server's
     * answer — sent, held back by its match mode, or not sent and why — or, unconnected, at once
     * with "not connected". The server passes its own match mode: this stream sends no datagram.
     */
    public java.util.concurrent.CompletableFuture<touchline.transport.SendResult> switchOption(int robotId, String option,
                                                                                               boolean on) {
        Session s = session;
        if (s == null || s.socket == null || s.ended.get()) {
            return java.util.concurrent.CompletableFuture.completedFuture(
                    touchline.transport.SendResult.failed("not connected to " + shownUrl));
        }
        String id = "switch-" + requests.incrementAndGet();
        var answer = new java.util.concurrent.CompletableFuture<touchline.transport.SendResult>();
        answers.put(id, answer);
        answer.whenComplete((r, e) -> answers.remove(id));
        s.send(s.socket, new JSONObject().put("op", "switchOption").put("robot", robotId).put("option", option)
                .put("on", on).put("id", id).toString());
        return answer;
    }

    public RemoteStatus status() {
        Session s = session;
        return new RemoteStatus(state, shownUrl, detail, s == null ? 0 : s.channels.size(), received.get(), unusable.get(),
                problem);
    }

    private void connect() {
        if (closed) {
            return;
        }
        state = RemoteStatus.State.CONNECTING;
        Session s = new Session();
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

    private static String reason(Throwable t) {
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

    private synchronized void retryLater(String why) {
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

    private synchronized void connected(Session s) {
        session = s;
        state = RemoteStatus.State.CONNECTED;
        detail = "";
        subprotocol = s.socket == null || s.socket.getSubprotocol() == null ? "" : s.socket.getSubprotocol();
        s.watch();
    }

    /** Something from the server could not be used: counted, and the newest one said in the status. */
    private void unusable(String what) {
        unusable.incrementAndGet();
        problem = what;
    }

    /** The server advertised its channels: it really serves us (one that only says "too many viewers" does not). */
    private synchronized void welcomed() {
        backoff = FIRST_BACKOFF;
    }

    /** The server's name as its serverInfo says it; "" before the first one. */
    public String serverName() {
        return serverInfo.optString("name", "");
    }

    /** Whether the server said it offers {@code capability} (e.g. {@code parameters}, {@code clientPublish}). */
    public boolean offers(String capability) {
        JSONArray caps = serverInfo.optJSONArray("capabilities");
        for (int i = 0; caps != null && i < caps.length(); i++) {
            if (capability.equals(caps.optString(i))) {
                return true;
            }
        }
        return false;
    }

    /** The subprotocol the server chose on the current (or last) connection; "" before one. */
    public String subprotocol() {
        return subprotocol;
    }

    /** Connections lost since the start (each followed by a reconnection attempt after the backoff). */
    public long losses() {
        return losses.get();
    }

    /** Sends one JSON op on the current connection; false when there is none. */
    boolean sendText(String op) {
        Session s = session;
        if (s == null || s.socket == null || s.ended.get()) {
            return false;
        }
        s.send(s.socket, op);
        return true;
    }

    /** Sends one binary message on the current connection; false when there is none. */
    boolean sendBinary(byte[] message) {
        Session s = session;
        if (s == null || s.socket == null || s.ended.get()) {
            return false;
        }
        s.sendBinary(s.socket, message);
        return true;
    }

    @Override
    public void close() {
        closed = true;
        reconnects.shutdownNow();
        Session s = session;
        if (s != null && s.socket != null) {
            s.socket.abort();
        }
    }

    /** One connection: its channels and subscriptions (each subscribed under the channel's own id). */
    private final class Session implements WebSocket.Listener {

        final Map<Integer, StreamChannel> channels = new ConcurrentHashMap<>();
        /** Every id the server advertised on this connection: a message for another one is the server's fault. */
        private final java.util.Set<Integer> advertised = ConcurrentHashMap.newKeySet();
        private final StringBuilder text = new StringBuilder();
        private final ByteArrayOutputStream binary = new ByteArrayOutputStream();
        private final AtomicBoolean ended = new AtomicBoolean();
        private volatile String lastStatus = "";
        private volatile long heardNanos = System.nanoTime();
        private boolean oversize; // the message being read is over the limit: its parts are skipped
        private long oversizeBytes;
        private volatile java.util.concurrent.ScheduledFuture<?> watchdog;
        private CompletableFuture<WebSocket> sending = CompletableFuture.completedFuture(null);
        WebSocket socket;

        @Override
        public void onOpen(WebSocket ws) {
            socket = ws;
            connected(this);
            ws.request(1);
        }

        /** Checks now and then that the server still speaks; a silent one is dropped and called again. */
        void watch() {
            long every = Math.max(10, silence.toMillis() / 4);
            try {
                watchdog = reconnects.scheduleWithFixedDelay(() -> {
                    if (System.nanoTime() - heardNanos > silence.toNanos()) {
                        lost("the server sent nothing for " + silence.toMillis() / 1000.0 + " s");
                    }
                }, every, every, TimeUnit.MILLISECONDS);
            } catch (java.util.concurrent.RejectedExecutionException closing) {
                // closed meanwhile
            }
        }

        /** Whether one more part of {@code n} bytes fits the message being read; once it does not, the rest is skipped. */
        private boolean fits(int sofar, int n, boolean last) {
            if (!oversize && (long) sofar + n > maxMessageBytes) {
                oversize = true;
                oversizeBytes = sofar;
            }
            if (oversize) {
                oversizeBytes += n;
                if (last) {
                    unusable("a message of " + oversizeBytes + " bytes, over the limit of " + maxMessageBytes
                            + ": dropped");
                    oversize = false;
                    text.setLength(0);
                    binary.reset();
                }
                return false;
            }
            return true;
        }

        @Override
        public CompletionStage<?> onText(WebSocket ws, CharSequence part, boolean last) {
            heardNanos = System.nanoTime();
            if (fits(text.length(), part.length(), last)) {
                text.append(part);
                if (last) {
                    String op = text.toString();
                    text.setLength(0);
                    try {
                        op(ws, new JSONObject(op));
                    } catch (JSONException e) {
                        unusable("a text message that is not a JSON object: " + clip(op));
                    } catch (RuntimeException e) {
                        unusable("a text message that could not be used (" + e + "): " + clip(op));
                    }
                }
            }
            ws.request(1);
            return null;
        }

        private static String clip(String s) {
            return s.length() <= 80 ? s : s.substring(0, 80) + "…";
        }

        private void op(WebSocket ws, JSONObject o) {
            switch (o.optString("op")) {
                case "advertise" -> {
                    welcomed();
                    JSONArray list = o.optJSONArray("channels");
                    if (list == null) {
                        unusable("an advertise without a list of channels");
                        return;
                    }
                    JSONArray subscribe = new JSONArray();
                    for (int i = 0; i < list.length(); i++) {
                        if (channels.size() >= MAX_CHANNELS || advertised.size() >= MAX_CHANNELS) {
                            unusable("an advertise beyond the limit of " + MAX_CHANNELS + " channels: "
                                    + (list.length() - i) + " not read");
                            break;
                        }
                        JSONObject c = list.optJSONObject(i);
                        if (c == null) {
                            unusable("an advertised channel that is not a JSON object");
                            continue;
                        }
                        if (c.has("id")) {
                            advertised.add(c.optInt("id", -1));
                        }
                        try {
                            StreamChannel sc = reader.read(c);
                            if (sc != null && channels.putIfAbsent(sc.id(), sc) == null) {
                                subscribe.put(new JSONObject().put("id", sc.id()).put("channelId", sc.id()));
                            }
                        } catch (IllegalArgumentException e) {
                            unusable("channel " + c.opt("id") + " (" + c.optString("topic", "no topic") + "): "
                                    + e.getMessage());
                        }
                    }
                    if (!subscribe.isEmpty()) {
                        send(ws, new JSONObject().put("op", "subscribe").put("subscriptions", subscribe).toString());
                    }
                }
                case "unadvertise" -> {
                    JSONArray ids = o.optJSONArray("channelIds");
                    for (int i = 0; ids != null && i < ids.length(); i++) {
                        channels.remove(ids.optInt(i, -1));
                    }
                }
                case "status" -> {
                    var answer = o.has("id") ? answers.get(o.optString("id")) : null;
                    if (answer != null) { // the answer to a switchOption: 0 sent, 1 held back, 2 not sent
                        String why = o.optString("message", "");
                        answer.complete(switch (o.optInt("level", 2)) {
                            case 0 -> touchline.transport.SendResult.sent();
                            case 1 -> touchline.transport.SendResult.held(why);
                            default -> touchline.transport.SendResult.failed(why);
                        });
                        return;
                    }
                    lastStatus = o.optString("message", "");
                    detail = lastStatus;
                }
                case "serverInfo" -> serverInfo = o;
                case "" -> unusable("a JSON message without an op: " + clip(o.toString()));
                default -> replies.op(o); // parameter values, services, ops of newer servers
            }
        }

        /** Sends one text after the previous one went out (the JDK's WebSocket allows one send at a time). */
        private synchronized void send(WebSocket ws, String message) {
            sending = sending.thenCompose(x -> ws.sendText(message, true));
        }

        private synchronized void sendBinary(WebSocket ws, byte[] message) {
            sending = sending.thenCompose(x -> ws.sendBinary(ByteBuffer.wrap(message), true));
        }

        @Override
        public CompletionStage<?> onBinary(WebSocket ws, ByteBuffer part, boolean last) {
            heardNanos = System.nanoTime();
            if (fits(binary.size(), part.remaining(), last)) {
                if (last && binary.size() == 0) {
                    data(part.order(ByteOrder.LITTLE_ENDIAN));
                } else {
                    byte[] b = new byte[part.remaining()];
                    part.get(b);
                    binary.writeBytes(b);
                    if (last) {
                        data(ByteBuffer.wrap(binary.toByteArray()).order(ByteOrder.LITTLE_ENDIAN));
                        binary.reset();
                    }
                }
            }
            ws.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onPing(WebSocket ws, ByteBuffer message) {
            heardNanos = System.nanoTime();
            return WebSocket.Listener.super.onPing(ws, message);
        }

        /** Message data (op 1: subscription, log time, payload); the server's time (op 2) is not needed. */
        private void data(ByteBuffer m) {
            int op = m.hasRemaining() ? m.get() & 0xFF : -1;
            if (op == 0x02 && m.remaining() == 8) {
                return; // the server's time
            }
            if (op != 0x01 && replies.binary(op, m)) {
                return;
            }
            if (op != 0x01) {
                unusable(op < 0 ? "an empty binary message" : "a binary message of op " + op + " and "
                        + (m.remaining() + 1) + " bytes (not a message or the time)");
                return;
            }
            if (m.remaining() < 12) {
                unusable("a message data of " + (m.remaining() + 1) + " bytes, too short for its header");
                return;
            }
            int id = m.getInt();
            StreamChannel c = channels.get(id);
            long timeNanos = m.getLong();
            if (c == null) {
                if (!advertised.contains(id)) {
                    unusable("a message for channel " + Integer.toUnsignedString(id) + ", which was never advertised");
                }
                return; // unadvertised meanwhile
            }
            byte[] payload = new byte[m.remaining()];
            m.get(payload);
            try {
                sink.accept(c.rebuild(payload, timeNanos));
                received.incrementAndGet();
            } catch (IOException | RuntimeException e) {
                unusable("a message on " + c.topic() + " that could not be rebuilt: " + e.getMessage());
            }
        }

        @Override
        public CompletionStage<?> onClose(WebSocket ws, int statusCode, String reason) {
            lost("closed by the server" + (reason == null || reason.isEmpty() ? "" : ": " + reason));
            return null;
        }

        @Override
        public void onError(WebSocket ws, Throwable error) {
            lost(reason(error));
        }

        void lost(String why) {
            if (ended.compareAndSet(false, true)) {
                if (watchdog != null) {
                    watchdog.cancel(false);
                }
                if (socket != null) {
                    socket.abort();
                }
                retryLater(lastStatus.isEmpty() ? why : why + "; the server said: " + lastStatus);
            }
        }
    }
}
