package touchline.transport.remote;

import org.json.JSONObject;
import touchline.protocol.FrameCodec;
import touchline.protocol.MessageCodec;
import touchline.transport.EnvelopeSink;
import touchline.transport.SendResult;

import javax.net.ssl.SSLContext;
import java.net.URI;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Another Touchline's live stream as envelopes: connects to its Foxglove WebSocket server
 * ({@code ws://} or {@code wss://}, with the token in the URL) through a {@link FoxgloveConnection},
 * subscribes to every robot channel it advertises (now and later), rebuilds each message into
 * the envelope the remote console saw and hands it to {@code sink}. A lost or refused connection
 * is a status, never an exception: it reconnects by itself with a doubling backoff. Read-only,
 * like the server: it sends nothing but subscriptions and the option switches the serving
 * console passes through its own match mode.
 */
public final class RemoteStream implements AutoCloseable {

    /** The query by which a Touchline server also advertises its channels of bytes (serve.Viewer's parameter). */
    static final String BYTES_QUERY = "raw=1";

    private final FoxgloveConnection connection;
    private final AtomicLong requests = new AtomicLong();
    private final Map<String, CompletableFuture<SendResult>> answers = new ConcurrentHashMap<>();

    /**
     * @param uri        e.g. {@code ws://10.0.0.5:8765/?token=…}
     * @param tls        trust for {@code wss://} (see {@link RemoteTrust}), or null for the JDK's default
     * @param codec      decodes the rebuilt FUmanoids messages (its kinds name the extensions, a team's included)
     * @param sink       where the envelopes go (the console's Envelope stream)
     * @param maxBackoff the longest wait between reconnection attempts
     */
    public RemoteStream(URI uri, SSLContext tls, MessageCodec codec, EnvelopeSink sink, Duration maxBackoff) {
        this(uri, tls, codec, sink, maxBackoff, FoxgloveConnection.MAX_MESSAGE_BYTES, FoxgloveConnection.SILENCE,
                FoxgloveConnection.HANDSHAKE);
    }

    /** As above, with the limits a test can make small: the largest message, the longest silence and handshake. */
    RemoteStream(URI uri, SSLContext tls, MessageCodec codec, EnvelopeSink sink, Duration maxBackoff,
                 int maxMessageBytes, Duration silence, Duration handshake) {
        this.connection = new FoxgloveConnection(withBytesQuery(uri), tls, touchlineChannels(codec), new Answers(), sink,
                maxBackoff, maxMessageBytes, silence, handshake);
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
        connection.start();
        return this;
    }

    /**
     * Asks the serving console to switch robot {@code robotId}'s {@code option} on or off (a
     * Touchline server offers it to tools on its own machine); completes with the server's
     * answer — sent, held back by its match mode, or not sent and why — or, unconnected, at once
     * with "not connected". The server passes its own match mode: this stream sends no datagram.
     */
    public CompletableFuture<SendResult> switchOption(int robotId, String option, boolean on) {
        String id = "switch-" + requests.incrementAndGet();
        var answer = new CompletableFuture<SendResult>();
        answers.put(id, answer);
        answer.whenComplete((r, e) -> answers.remove(id));
        if (!connection.sendText(new JSONObject().put("op", "switchOption").put("robot", robotId).put("option", option)
                .put("on", on).put("id", id).toString())) {
            answer.complete(SendResult.failed("not connected to " + connection.shownUrl()));
        }
        return answer;
    }

    public RemoteStatus status() {
        return connection.status();
    }

    @Override
    public void close() {
        connection.close();
    }

    /** The serving console's answers to option switches: a status with the switch's id, 0 sent, 1 held back, 2 not sent. */
    private final class Answers implements ServerReplies {

        @Override
        public boolean answer(JSONObject status) {
            var answer = answers.get(status.optString("id"));
            if (answer == null) {
                return false;
            }
            String why = status.optString("message", "");
            answer.complete(switch (status.optInt("level", 2)) {
                case 0 -> SendResult.sent();
                case 1 -> SendResult.held(why);
                default -> SendResult.failed(why);
            });
            return true;
        }

        @Override
        public void op(JSONObject o) {
            // a Touchline server sends no other ops
        }

        @Override
        public boolean binary(int op, ByteBuffer rest) {
            return false;
        }
    }
}
