package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * One connection of a {@link FoxgloveConnection}: reads the server's ops (advertise,
 * unadvertise, status, serverInfo; the rest to the connection's {@link ServerReplies}) and
 * message data, its channels and subscriptions (each subscribed under the channel's own id),
 * within the connection's limits of message size, channels and silence.
 */
final class FoxgloveSession implements WebSocket.Listener {

    private final FoxgloveConnection connection;
    private final Map<Integer, StreamChannel> channels = new ConcurrentHashMap<>();
    /** Every id the server advertised on this connection: a message for another one is the server's fault. */
    private final Set<Integer> advertised = ConcurrentHashMap.newKeySet();
    private final StringBuilder text = new StringBuilder();
    private final ByteArrayOutputStream binary = new ByteArrayOutputStream();
    private final AtomicBoolean ended = new AtomicBoolean();
    private volatile String lastStatus = "";
    private volatile long heardNanos = System.nanoTime();
    private boolean oversize; // the message being read is over the limit: its parts are skipped
    private long oversizeBytes;
    private volatile ScheduledFuture<?> watchdog;
    private CompletableFuture<WebSocket> sending = CompletableFuture.completedFuture(null);
    volatile WebSocket socket;

    FoxgloveSession(FoxgloveConnection connection) {
        this.connection = connection;
    }

    int channels() {
        return channels.size();
    }

    @Override
    public void onOpen(WebSocket ws) {
        socket = ws;
        connection.connected(this);
        ws.request(1);
    }

    /** Checks now and then that the server still speaks; a silent one is dropped and called again. */
    void watch() {
        long every = Math.max(10, connection.silence.toMillis() / 4);
        try {
            watchdog = connection.reconnects.scheduleWithFixedDelay(() -> {
                if (System.nanoTime() - heardNanos > connection.silence.toNanos()) {
                    lost("the server sent nothing for " + connection.silence.toMillis() / 1000.0 + " s");
                }
            }, every, every, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException closing) {
            // closed meanwhile
        }
    }

    /** Whether one more part of {@code n} bytes fits the message being read; once it does not, the rest is skipped. */
    private boolean fits(int sofar, int n, boolean last) {
        int max = connection.maxMessageBytes;
        if (!oversize && (long) sofar + n > max) {
            oversize = true;
            oversizeBytes = sofar;
        }
        if (oversize) {
            oversizeBytes += n;
            if (last) {
                connection.unusable("a message of " + oversizeBytes + " bytes, over the limit of " + max + ": dropped");
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
                    op(new JSONObject(op));
                } catch (JSONException e) {
                    connection.unusable("a text message that is not a JSON object: " + clip(op));
                } catch (RuntimeException e) {
                    connection.unusable("a text message that could not be used (" + e + "): " + clip(op));
                }
            }
        }
        ws.request(1);
        return null;
    }

    private static String clip(String s) {
        return s.length() <= 80 ? s : s.substring(0, 80) + "…";
    }

    private void op(JSONObject o) {
        switch (o.optString("op")) {
            case "advertise" -> advertise(o);
            case "unadvertise" -> {
                JSONArray ids = o.optJSONArray("channelIds");
                for (int i = 0; ids != null && i < ids.length(); i++) {
                    channels.remove(ids.optInt(i, -1));
                }
            }
            case "status" -> {
                if (o.has("id") && connection.replies.answer(o)) {
                    return;
                }
                lastStatus = o.optString("message", "");
                connection.said(lastStatus);
            }
            case "serverInfo" -> connection.serverInfo(o);
            case "" -> connection.unusable("a JSON message without an op: " + clip(o.toString()));
            default -> connection.replies.op(o); // parameter values, services, ops of newer servers
        }
    }

    private void advertise(JSONObject o) {
        connection.welcomed();
        JSONArray list = o.optJSONArray("channels");
        if (list == null) {
            connection.unusable("an advertise without a list of channels");
            return;
        }
        int max = FoxgloveConnection.MAX_CHANNELS;
        JSONArray subscribe = new JSONArray();
        for (int i = 0; i < list.length(); i++) {
            if (channels.size() >= max || advertised.size() >= max) {
                connection.unusable("an advertise beyond the limit of " + max + " channels: " + (list.length() - i)
                        + " not read");
                break;
            }
            JSONObject c = list.optJSONObject(i);
            if (c == null) {
                connection.unusable("an advertised channel that is not a JSON object");
                continue;
            }
            if (c.has("id")) {
                advertised.add(c.optInt("id", -1));
            }
            try {
                StreamChannel sc = connection.reader.read(c);
                if (sc != null && channels.putIfAbsent(sc.id(), sc) == null) {
                    subscribe.put(new JSONObject().put("id", sc.id()).put("channelId", sc.id()));
                }
            } catch (IllegalArgumentException e) {
                connection.unusable("channel " + c.opt("id") + " (" + c.optString("topic", "no topic") + "): "
                        + e.getMessage());
            }
        }
        if (!subscribe.isEmpty()) {
            sendText(new JSONObject().put("op", "subscribe").put("subscriptions", subscribe).toString());
        }
    }

    /** Sends one text after the previous one went out (the JDK's WebSocket allows one send at a time); false when ended. */
    synchronized boolean sendText(String message) {
        WebSocket ws = socket;
        if (ws == null || ended.get()) {
            return false;
        }
        sending = sending.thenCompose(x -> ws.sendText(message, true));
        return true;
    }

    synchronized boolean sendBinary(byte[] message) {
        WebSocket ws = socket;
        if (ws == null || ended.get()) {
            return false;
        }
        sending = sending.thenCompose(x -> ws.sendBinary(ByteBuffer.wrap(message), true));
        return true;
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
        if (op != 0x01 && connection.replies.binary(op, m)) {
            return;
        }
        if (op != 0x01) {
            connection.unusable(op < 0 ? "an empty binary message" : "a binary message of op " + op + " and "
                    + (m.remaining() + 1) + " bytes (not a message or the time)");
            return;
        }
        if (m.remaining() < 12) {
            connection.unusable("a message data of " + (m.remaining() + 1) + " bytes, too short for its header");
            return;
        }
        int id = m.getInt();
        StreamChannel c = channels.get(id);
        long timeNanos = m.getLong();
        if (c == null) {
            if (!advertised.contains(id)) {
                connection.unusable("a message for channel " + Integer.toUnsignedString(id) + ", which was never advertised");
            }
            return; // unadvertised meanwhile
        }
        byte[] payload = new byte[m.remaining()];
        m.get(payload);
        try {
            connection.sink.accept(c.rebuild(payload, timeNanos));
            connection.received();
        } catch (IOException | RuntimeException e) {
            connection.unusable("a message on " + c.topic() + " that could not be rebuilt: " + e.getMessage());
        }
    }

    @Override
    public CompletionStage<?> onClose(WebSocket ws, int statusCode, String reason) {
        lost("closed by the server" + (reason == null || reason.isEmpty() ? "" : ": " + reason));
        return null;
    }

    @Override
    public void onError(WebSocket ws, Throwable error) {
        lost(FoxgloveConnection.reason(error));
    }

    void abort() {
        WebSocket ws = socket;
        if (ws != null) {
            ws.abort();
        }
    }

    void lost(String why) {
        if (ended.compareAndSet(false, true)) {
            if (watchdog != null) {
                watchdog.cancel(false);
            }
            abort();
            connection.retryLater(lastStatus.isEmpty() ? why : why + "; the server said: " + lastStatus);
        }
    }
}
