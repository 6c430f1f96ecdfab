package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONObject;
import touchline.transport.EnvelopeSink;
import touchline.transport.Hold;
import touchline.transport.MicrosClock;
import touchline.transport.SendGate;
import touchline.transport.SendResult;

import javax.net.ssl.SSLContext;
import java.net.InetSocketAddress;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A robot behind a Foxglove WebSocket server (a ROS 2 robot's {@code foxglove_bridge}, any
 * server made with the Foxglove SDK, an older {@code foxglove.websocket.v1} one): subscribes to
 * every channel it advertises and hands each message to {@code sink} as an envelope of robot
 * {@code robotId}. Reconnects by itself with a doubling backoff, like {@link RemoteStream}
 * (both ride on {@link FoxgloveConnection}). Its commands — setting a parameter, publishing on a topic, calling a
 * service — ask {@code gate} first: held while match mode says so (the latest of each held
 * command goes out when {@link #sendHeld} finds the gate open again), refused when the gate
 * refuses for good.
 */
public final class Bridge implements AutoCloseable {

    /** A parameter of the robot's as the server last reported it; {@code value} is JSON (a number, bool, string, list). */
    public record Parameter(String name, Object value, String type) {

        public boolean isBool() {
            return value instanceof Boolean;
        }
    }

    /** A held command (the latest per parameter and per topic is kept; older ones are replaced). */
    private record Held(String key, String op, byte[] binary, String what) { }

    static final int MAX_HELD = 64;

    private final String name;
    private final int robotId;
    private final SendGate gate;
    private final FoxgloveConnection stream;
    private final BridgeChannels channels;
    private final Map<String, Parameter> parameters = new TreeMap<>();
    private final Map<String, Held> held = new java.util.LinkedHashMap<>();
    private final Map<String, Integer> clientChannels = new TreeMap<>();
    private final BridgeServices services = new BridgeServices();
    private final AtomicInteger requests = new AtomicInteger();
    private volatile long parametersVersion;
    private volatile String lastCommand = "";

    /**
     * @param name     the robot's name in the Robots table ({@code booster-1})
     * @param uri      {@code ws://HOST:8765/} (or {@code wss://})
     * @param robotId  the robot number its envelopes carry (the team's bridges are numbered apart from UDP robots)
     * @param gate     the console's send gate (match mode, a viewing console)
     */
    public Bridge(String name, URI uri, SSLContext tls, int robotId, MicrosClock clock, EnvelopeSink sink, SendGate gate,
                  Duration maxBackoff) {
        this.name = name;
        this.robotId = robotId;
        this.gate = gate;
        InetSocketAddress peer = InetSocketAddress.createUnresolved(uri.getHost() == null ? "?" : uri.getHost(),
                uri.getPort() < 0 ? 8765 : uri.getPort());
        this.channels = new BridgeChannels(robotId, peer, clock);
        this.stream = new FoxgloveConnection(uri, tls, channels, new Replies(), sink,
                maxBackoff, FoxgloveConnection.MAX_MESSAGE_BYTES, Duration.ofDays(1), FoxgloveConnection.HANDSHAKE);
    }

    public Bridge start() {
        stream.start();
        return this;
    }

    public String name() {
        return name;
    }

    public int robotId() {
        return robotId;
    }

    /** Where the connection stands, with what the server said of itself and what was counted. */
    public BridgeStatus status() {
        RemoteStatus s = stream.status();
        return new BridgeStatus(name, robotId, s, stream.serverName(), stream.subprotocol(), stream.losses(),
                lastCommand, channels.undecodable());
    }

    /** The encoding and schema the server advertised for {@code topic}, or null (for the recorder). */
    public BridgedSchema schema(String topic) {
        return channels.schema(topic);
    }

    /** Whether the server offers {@code capability} ({@code parameters}, {@code clientPublish}, {@code services}). */
    public boolean offers(String capability) {
        return stream.offers(capability);
    }

    /** The robot's parameters as last reported, by name. */
    public synchronized List<Parameter> parameters() {
        return new ArrayList<>(parameters.values());
    }

    /** Changes whenever parameter values arrive. */
    public long parametersVersion() {
        return parametersVersion;
    }

    /** The services the server advertised, by name. */
    public List<String> services() {
        return services.names();
    }

    /** What the robot answered to the latest service calls (responses and failures), oldest first. */
    public List<ServiceAnswer> serviceAnswers() {
        return services.answers();
    }

    /** Asks for every parameter (the answer fills {@link #parameters}); reading passes no gate. */
    public SendResult refreshParameters() {
        if (!stream.offers("parameters")) {
            return SendResult.failed(name + " offers no parameters");
        }
        return sent(stream.sendText(new JSONObject().put("op", "getParameters").put("parameterNames", new JSONArray())
                .put("id", "get-" + requests.incrementAndGet()).toString()));
    }

    /** Sets one parameter ({@code value}: Boolean, Number, String); passes the gate. */
    public SendResult setParameter(String parameter, Object value) {
        if (!stream.offers("parameters")) {
            return SendResult.failed(name + " offers no parameters");
        }
        String op = new JSONObject().put("op", "setParameters")
                .put("parameters", new JSONArray().put(new JSONObject().put("name", parameter).put("value", value)))
                .put("id", "set-" + requests.incrementAndGet()).toString();
        return command(new Held("parameter " + parameter, op, null, parameter + " = " + value));
    }

    /**
     * Publishes one message on {@code topic} (client publish), the values typed as JSON: in CDR by
     * the type's ROS 2 definition when the server takes CDR and the definition is known (or it
     * takes nothing else), else as the JSON text (see {@link ClientEncoding}); passes the gate.
     */
    public SendResult publish(String topic, String schemaName, String json) {
        if (!stream.offers("clientPublish")) {
            return SendResult.failed(name + " takes no client messages");
        }
        Outgoing out = new ClientEncoding(stream.serverInfo()).write(schemaName, channels.ros2Schema(topic, schemaName),
                "", json);
        if (out instanceof Outgoing.Refused r) {
            lastCommand = topic + ": " + r.reason();
            return SendResult.failed(r.reason());
        }
        Outgoing.Ready m = (Outgoing.Ready) out;
        int channel;
        synchronized (this) {
            channel = clientChannels.computeIfAbsent(topic, t -> clientChannels.size() + 1);
        }
        JSONObject advertised = new JSONObject().put("id", channel).put("topic", topic).put("encoding", m.encoding())
                .put("schemaName", m.schema() == null ? schemaName : m.schema().schemaName());
        if (m.schema() != null) {
            advertised.put("schemaEncoding", m.schema().schemaEncoding())
                    .put("schema", new String(m.schema().schemaData(), StandardCharsets.UTF_8));
        }
        String advertise = new JSONObject().put("op", "advertise").put("channels", new JSONArray().put(advertised))
                .toString();
        byte[] data = ByteBuffer.allocate(5 + m.payload().length).order(ByteOrder.LITTLE_ENDIAN).put((byte) 0x01)
                .putInt(channel).put(m.payload()).array();
        return command(new Held("publish " + topic, advertise, data, topic + " (" + m.encoding() + "): " + json));
    }

    /**
     * Calls service {@code service} with a request typed as JSON, written as the service takes it
     * (CDR by its request definition, or JSON); passes the gate. The answer arrives in
     * {@link #serviceAnswers}.
     */
    public SendResult callService(String service, String json) {
        if (!stream.offers("services") || !services.has(service)) {
            return SendResult.failed(name + " offers no service " + service);
        }
        Outgoing out = services.call(service, json, stream.serverInfo());
        if (out instanceof Outgoing.Refused r) {
            lastCommand = service + ": " + r.reason();
            return SendResult.failed(r.reason());
        }
        return command(new Held("call " + service, null, ((Outgoing.Ready) out).payload(), service + "(" + json + ")"));
    }

    /** A command through the gate: sent now, or held (the newest per key) until play stops. */
    private SendResult command(Held c) {
        Optional<Hold> hold = gate.hold();
        if (hold.isPresent() && !hold.get().untilPlayStops()) {
            lastCommand = c.what() + ": " + hold.get().why();
            return SendResult.failed(hold.get().why());
        }
        if (hold.isPresent()) {
            synchronized (this) {
                held.remove(c.key());
                if (held.size() < MAX_HELD) {
                    held.put(c.key(), c);
                }
            }
            lastCommand = c.what() + ": held back: " + hold.get().queued();
            return SendResult.held(hold.get().queued());
        }
        SendResult r = send(c);
        lastCommand = c.what() + ": " + r.describe();
        return r;
    }

    private SendResult send(Held c) {
        boolean ok = c.op() == null || stream.sendText(c.op());
        ok = ok && (c.binary() == null || stream.sendBinary(c.binary()));
        return sent(ok);
    }

    private SendResult sent(boolean ok) {
        return ok ? SendResult.sent() : SendResult.failed("not connected to " + stream.status().url());
    }

    /** The held commands, in words. */
    public synchronized List<String> held() {
        return held.values().stream().map(Held::what).toList();
    }

    /** Sends what was held once the gate is open again (the console's tick calls it); returns how many went out. */
    public int sendHeld() {
        if (gate.hold().isPresent()) {
            return 0;
        }
        List<Held> due;
        synchronized (this) {
            due = new ArrayList<>(held.values());
            held.clear();
        }
        int n = 0;
        for (Held c : due) {
            SendResult r = send(c);
            lastCommand = c.what() + ": " + (r.isSent() ? "sent after play" : r.describe());
            n += r.isSent() ? 1 : 0;
        }
        return n;
    }

    @Override
    public void close() {
        stream.close();
    }

    /** The server's parameter values and services. */
    private final class Replies implements ServerReplies {

        @Override
        public void op(JSONObject o) {
            switch (o.optString("op")) {
                case "parameterValues" -> {
                    JSONArray list = o.optJSONArray("parameters");
                    synchronized (Bridge.this) {
                        for (int i = 0; list != null && i < list.length(); i++) {
                            JSONObject p = list.optJSONObject(i);
                            if (p != null && !p.optString("name").isEmpty()) {
                                Object v = p.opt("value");
                                parameters.put(p.getString("name"), new Parameter(p.getString("name"),
                                        v == null || v == JSONObject.NULL ? null : v, p.optString("type", "")));
                            }
                        }
                    }
                    parametersVersion++;
                }
                case "advertiseServices" -> services.advertised(o.optJSONArray("services"));
                case "unadvertiseServices" -> services.unadvertised(o.optJSONArray("serviceIds"));
                case "serviceCallFailure" -> services.failure(o);
                default -> { } // connection graph, playback state: not used
            }
        }

        @Override
        public boolean binary(int op, ByteBuffer rest) {
            if (op == 0x03) { // service call response: service id, call id, encoding, payload
                services.response(rest);
                return true;
            }
            return false;
        }
    }
}
