package touchline.serve;

import org.json.JSONObject;

import java.util.Arrays;

/**
 * One advertised channel: a robot's message kind (e.g. {@code /robot/3/status}) or a console
 * state, with its schema and the subscriptions messages go to. Subscribers change rarely and
 * are read for every message, so they are copied on write.
 */
final class ServedChannel {

    private final int id;
    private final String topic;
    private final String encoding;
    private final String schemaName;
    private final String schema;
    private final String schemaEncoding;
    private final ChannelSchema payloads; // null for the console's JSON state channels
    private volatile Subscription[] subscribers = new Subscription[0];
    private volatile byte[] latest; // a state channel's current value, sent to each new subscriber

    ServedChannel(int id, String topic, String encoding, String schemaName, String schema, String schemaEncoding,
                  ChannelSchema payloads) {
        this.id = id;
        this.topic = topic;
        this.encoding = encoding;
        this.schemaName = schemaName;
        this.schema = schema;
        this.schemaEncoding = schemaEncoding;
        this.payloads = payloads;
    }

    int id() {
        return id;
    }

    String topic() {
        return topic;
    }

    /** How this channel's envelopes become payloads; null for a state channel. */
    ChannelSchema payloads() {
        return payloads;
    }

    /** A state channel's current value, or null (message channels keep nothing). */
    byte[] latest() {
        return latest;
    }

    void setLatest(byte[] value) {
        latest = value;
    }

    Subscription[] subscribers() {
        return subscribers;
    }

    synchronized void add(Subscription s) {
        Subscription[] now = Arrays.copyOf(subscribers, subscribers.length + 1);
        now[now.length - 1] = s;
        subscribers = now;
    }

    synchronized void remove(Subscription s) {
        subscribers = Arrays.stream(subscribers).filter(x -> x != s).toArray(Subscription[]::new);
    }

    /** The channel as the Advertise op lists it. */
    JSONObject advertisement() {
        return new JSONObject().put("id", id).put("topic", topic).put("encoding", encoding)
                .put("schemaName", schemaName).put("schema", schema).put("schemaEncoding", schemaEncoding);
    }
}
