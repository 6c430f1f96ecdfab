package touchline.transport.remote;

import org.json.JSONObject;
import touchline.protocol.ros2.ChannelDecoders;
import touchline.protocol.ros2.ChannelDecoding;
import touchline.transport.MicrosClock;

import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;

/**
 * Every channel a robot's Foxglove server advertises, read as that robot's: {@code protobuf}
 * by the advertised descriptor set; {@code cdr} ({@code ros2msg}/{@code ros2idl}) and {@code json}
 * (with a JSON schema or none) by {@link ChannelDecoders}. A channel in an encoding Touchline
 * does not read, or whose definition does not parse, is refused (counted, not subscribed).
 */
final class BridgeChannels implements ChannelReader {

    /** The largest schema taken from an advertise: a ROS 2 definition with its dependencies is a few KB. */
    static final int MAX_SCHEMA_CHARS = 1 << 20;

    private final int robotId;
    private final InetSocketAddress peer;
    private final MicrosClock clock;
    private final ChannelDecoders decoders = new ChannelDecoders();
    private final java.util.Map<String, BridgedSchema> schemas = new java.util.concurrent.ConcurrentHashMap<>();
    /** The channels made, by topic (at most {@link FoxgloveConnection#MAX_CHANNELS} a connection), for their counts. */
    private final java.util.Map<String, BridgedChannel> made = new java.util.concurrent.ConcurrentHashMap<>();

    BridgeChannels(int robotId, InetSocketAddress peer, MicrosClock clock) {
        this.robotId = robotId;
        this.peer = peer;
        this.clock = clock;
    }

    @Override
    public StreamChannel read(JSONObject c) {
        if (!(c.opt("id") instanceof Number)) {
            throw new IllegalArgumentException("no channel id");
        }
        int id = c.getInt("id");
        String topic = c.optString("topic", "");
        String encoding = c.optString("encoding", "");
        String schemaName = c.optString("schemaName", "");
        String schemaEncoding = c.optString("schemaEncoding", "");
        String schema = c.optString("schema", "");
        if (topic.isEmpty()) {
            throw new IllegalArgumentException("no topic");
        }
        if (schema.length() > MAX_SCHEMA_CHARS) {
            throw new IllegalArgumentException("a schema of " + schema.length() + " characters, over the limit of "
                    + MAX_SCHEMA_CHARS);
        }
        if (encoding.equals("protobuf")) {
            BridgedChannel bridged = new BridgedChannel(id, topic, RemoteChannel.schema(schema, schemaName), robotId, peer,
                    clock);
            schemas.put(topic, new BridgedSchema(encoding, schemaName, schemaEncoding,
                    java.util.Base64.getDecoder().decode(schema)));
            return made(bridged);
        }
        ChannelDecoding d = decoders.decoding(topic, encoding, schemaName, schemaEncoding,
                schema.getBytes(StandardCharsets.UTF_8));
        if (d instanceof ChannelDecoding.Ready r) {
            schemas.put(topic, new BridgedSchema(encoding, schemaName, schemaEncoding,
                    schema.getBytes(StandardCharsets.UTF_8)));
            return made(new BridgedChannel(id, topic, encoding, r.decoder(), robotId, peer, clock));
        }
        ChannelDecoding.Unsupported u = (ChannelDecoding.Unsupported) d;
        throw new IllegalArgumentException(u.encoding() + ": " + u.reason());
    }

    private BridgedChannel made(BridgedChannel c) {
        made.put(c.topic(), c);
        return c;
    }

    /** Messages that did not decode, by topic: only the topics with any, sorted. */
    java.util.SortedMap<String, Long> undecodable() {
        java.util.SortedMap<String, Long> out = new java.util.TreeMap<>();
        made.forEach((topic, c) -> {
            if (c.undecodable() > 0) {
                out.put(topic, c.undecodable());
            }
        });
        return out;
    }

    /**
     * The ROS 2 definition a message of type {@code schemaName} on {@code topic} is written by: the
     * topic's own when the server advertised it with a {@code ros2msg}/{@code ros2idl} schema, else
     * that of any channel of the same type; null when none is known.
     */
    BridgedSchema ros2Schema(String topic, String schemaName) {
        BridgedSchema own = schemas.get(topic);
        if (own != null && own.isRos2()) {
            return own;
        }
        return schemas.values().stream().filter(s -> s.isRos2() && s.schemaName().equals(schemaName)).findFirst()
                .orElse(null);
    }

    /** The schema the server advertised for {@code topic}, or null. */
    BridgedSchema schema(String topic) {
        return schemas.get(topic);
    }
}
