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
    static final Duration FIRST_BACKOFF = Duration.ofMillis(250);

    private final URI uri;
    private final String shownUrl;
    private final HttpClient http;
    private final EnvelopeSink sink;
    private final MessageCodec codec;
    private final FrameCodec frames = new FrameCodec(Integer.MAX_VALUE);
    private final Duration maxBackoff;
    private final ScheduledExecutorService reconnects;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong unusable = new AtomicLong();
    private volatile RemoteStatus.State state = RemoteStatus.State.CONNECTING;
    private volatile String detail = "";
    private volatile Session session;
    private volatile boolean closed;
    private Duration backoff = FIRST_BACKOFF;

    /**
     * @param uri        e.g. {@code ws://10.0.0.5:8765/?token=…}
     * @param tls        trust for {@code wss://} (see {@link RemoteTrust}), or null for the JDK's default
     * @param codec      decodes the rebuilt FUmanoids messages (its kinds name the extensions, a team's included)
     * @param sink       where the envelopes go (the console's Envelope stream)
     * @param maxBackoff the longest wait between reconnection attempts
     */
    public RemoteStream(URI uri, SSLContext tls, MessageCodec codec, EnvelopeSink sink, Duration maxBackoff) {
        String scheme = uri.getScheme() == null ? "" : uri.getScheme().toLowerCase(java.util.Locale.ROOT);
        if (!scheme.equals("ws") && !scheme.equals("wss")) {
            throw new IllegalArgumentException("not a WebSocket URL (ws://HOST:PORT/?token=… or wss://…): " + uri);
        }
        this.uri = uri;
        this.shownUrl = scheme + "://" + uri.getHost() + (uri.getPort() < 0 ? "" : ":" + uri.getPort()) + "/";
        HttpClient.Builder b = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5));
        if (tls != null) {
            b.sslContext(tls);
        }
        this.http = b.build();
        this.codec = codec;
        this.sink = sink;
        this.maxBackoff = maxBackoff;
        this.reconnects = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "touchline-remote");
            t.setDaemon(true);
            return t;
        });
    }

    /** Starts connecting; returns at once (the status says how it goes). */
    public RemoteStream start() {
        reconnects.execute(this::connect);
        return this;
    }

    public RemoteStatus status() {
        Session s = session;
        return new RemoteStatus(state, shownUrl, detail, s == null ? 0 : s.channels.size(), received.get(), unusable.get());
    }

    private void connect() {
        if (closed) {
            return;
        }
        state = RemoteStatus.State.CONNECTING;
        Session s = new Session();
        http.newWebSocketBuilder().subprotocols(SUBPROTOCOL).connectTimeout(Duration.ofSeconds(5))
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
        long wait = backoff.toMillis();
        backoff = backoff.multipliedBy(2).compareTo(maxBackoff) > 0 ? maxBackoff : backoff.multipliedBy(2);
        reconnects.schedule(this::connect, wait, TimeUnit.MILLISECONDS);
    }

    private synchronized void connected(Session s) {
        session = s;
        state = RemoteStatus.State.CONNECTED;
        detail = "";
    }

    /** The server advertised its channels: it really serves us (one that only says "too many viewers" does not). */
    private synchronized void welcomed() {
        backoff = FIRST_BACKOFF;
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

        final Map<Integer, RemoteChannel> channels = new ConcurrentHashMap<>();
        private final StringBuilder text = new StringBuilder();
        private final ByteArrayOutputStream binary = new ByteArrayOutputStream();
        private final AtomicBoolean ended = new AtomicBoolean();
        private volatile String lastStatus = "";
        private CompletableFuture<WebSocket> sending = CompletableFuture.completedFuture(null);
        WebSocket socket;

        @Override
        public void onOpen(WebSocket ws) {
            socket = ws;
            connected(this);
            ws.request(1);
        }

        @Override
        public CompletionStage<?> onText(WebSocket ws, CharSequence part, boolean last) {
            text.append(part);
            if (last) {
                String op = text.toString();
                text.setLength(0);
                try {
                    op(ws, new JSONObject(op));
                } catch (JSONException e) {
                    unusable.incrementAndGet();
                }
            }
            ws.request(1);
            return null;
        }

        private void op(WebSocket ws, JSONObject o) {
            switch (o.optString("op")) {
                case "advertise" -> {
                    welcomed();
                    JSONArray list = o.optJSONArray("channels");
                    JSONArray subscribe = new JSONArray();
                    for (int i = 0; list != null && i < list.length(); i++) {
                        JSONObject c = list.optJSONObject(i);
                        if (c == null || c.optJSONObject("metadata") == null) {
                            continue; // a JSON state channel, or not a Touchline's
                        }
                        try {
                            RemoteChannel rc = RemoteChannel.of(c, codec, frames);
                            if (channels.putIfAbsent(rc.id(), rc) == null) {
                                subscribe.put(new JSONObject().put("id", rc.id()).put("channelId", rc.id()));
                            }
                        } catch (IllegalArgumentException e) {
                            unusable.incrementAndGet();
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
                    lastStatus = o.optString("message", "");
                    detail = lastStatus;
                }
                default -> { } // serverInfo and ops of newer servers: nothing to do
            }
        }

        /** Sends one text after the previous one went out (the JDK's WebSocket allows one send at a time). */
        private synchronized void send(WebSocket ws, String message) {
            sending = sending.thenCompose(x -> ws.sendText(message, true));
        }

        @Override
        public CompletionStage<?> onBinary(WebSocket ws, ByteBuffer part, boolean last) {
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
            ws.request(1);
            return null;
        }

        /** Message data (op 1: subscription, log time, payload); the server's time (op 2) is not needed. */
        private void data(ByteBuffer m) {
            if (m.remaining() < 13 || m.get() != 0x01) {
                return;
            }
            RemoteChannel c = channels.get(m.getInt());
            long timeNanos = m.getLong();
            if (c == null) {
                return; // unsubscribed meanwhile
            }
            byte[] payload = new byte[m.remaining()];
            m.get(payload);
            try {
                sink.accept(c.rebuild(payload, timeNanos));
                received.incrementAndGet();
            } catch (IOException | RuntimeException e) {
                unusable.incrementAndGet();
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
                if (socket != null) {
                    socket.abort();
                }
                retryLater(lastStatus.isEmpty() ? why : why + "; the server said: " + lastStatus);
            }
        }
    }
}
