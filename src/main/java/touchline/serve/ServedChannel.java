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
    private final ChannelPayloads payloads; // null for the console's JSON state channels
    private final java.util.Map<String, String> metadata; // null: none advertised
    private volatile Subscription[] subscribers = new Subscription[0];
    private byte[] latest; // a state channel's current value, sent to each new subscriber (guarded by this)
    private long latestTimeNanos; // when it was heard, 0 for a console state (guarded by this)

    ServedChannel(int id, String topic, String encoding, String schemaName, String schema, String schemaEncoding,
                  ChannelPayloads payloads, java.util.Map<String, String> metadata) {
        this.id = id;
        this.topic = topic;
        this.encoding = encoding;
        this.schemaName = schemaName;
        this.schema = schema;
        this.schemaEncoding = schemaEncoding;
        this.payloads = payloads;
        this.metadata = metadata;
    }

    int id() {
        return id;
    }

    String topic() {
        return topic;
    }

    /**
     * A channel of bytes (what the console heard without a decoded message): no schema a
     * Foxglove viewer can read, so advertised only to a viewer that asked for them.
     */
    boolean bytes() {
        return payloads instanceof RawChannel;
    }

    /** How this channel's envelopes become payloads; null for a state channel. */
    ChannelPayloads payloads() {
        return payloads;
    }

    synchronized void setLatest(byte[] value) {
        latestTimeNanos = 0;
        latest = value;
    }

    /**
     * A robot's state-like message (its option list, its status): kept with the time it was
     * heard, for new subscribers; returns the subscribers to send it to now. Atomic with
     * {@link #add}: a subscription added before gets the value from the publisher (it is in the
     * returned array), one added after gets it from its catch-up — never neither (a viewer
     * subscribing while a status was being published missed it), never the same value twice.
     */
    synchronized Subscription[] latch(byte[] value, long timeNanos) {
        latestTimeNanos = timeNanos;
        latest = value;
        return subscribers;
    }

    /** The latched value at one moment and when it was heard (0: a console state, which holds now). */
    record Latched(byte[] value, long timeNanos) { }


    Subscription[] subscribers() {
        return subscribers;
    }

    /** Adds a subscriber; returns the latched value as it was then, which the subscriber catches up with. */
    synchronized Latched add(Subscription s) {
        Subscription[] now = Arrays.copyOf(subscribers, subscribers.length + 1);
        now[now.length - 1] = s;
        subscribers = now;
        return new Latched(latest, latestTimeNanos);
    }

    synchronized void remove(Subscription s) {
        subscribers = Arrays.stream(subscribers).filter(x -> x != s).toArray(Subscription[]::new);
    }

    /**
     * The channel as the Advertise op lists it. A robot's channel also carries {@code metadata}
     * (string to string, as in the recording's channels): an extra field other clients ignore,
     * from which another Touchline rebuilds the envelopes.
     */
    JSONObject advertisement() {
        JSONObject a = new JSONObject().put("id", id).put("topic", topic).put("encoding", encoding)
                .put("schemaName", schemaName).put("schema", schema).put("schemaEncoding", schemaEncoding);
        if (metadata != null) {
            a.put("metadata", new JSONObject(metadata));
        }
        return a;
    }
}
