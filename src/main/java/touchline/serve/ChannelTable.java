package touchline.serve;

import touchline.protocol.MessageKinds;
import touchline.record.Topics;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The channels served: one per robot, direction and message kind, named like the recorder's
 * topics, created (and advertised to every viewer) the first time such a message is seen.
 * A viewer that joins gets every channel known so far; creating a channel and welcoming a
 * viewer exclude each other, so no viewer misses a channel or hears of one twice. Bounded: robot
 * IDs and kinds come from the network, so past {@code maxChannels} new ones are counted and not served.
 */
final class ChannelTable {

    private record Key(Direction direction, Channel channel, int robotId, String kind, RawChannel raw) {
    }

    private final MessageKinds kinds;
    private final ViewerTable viewers;
    private final int maxChannels;
    private final Topics topics = new Topics();
    private final Map<Key, ServedChannel> byKey = new ConcurrentHashMap<>();
    private final Map<Integer, ServedChannel> byId = new ConcurrentHashMap<>();
    private final AtomicLong refused = new AtomicLong();
    private int nextId = 1;

    ChannelTable(MessageKinds kinds, ViewerTable viewers, int maxChannels) {
        this.kinds = kinds;
        this.viewers = viewers;
        this.maxChannels = maxChannels;
    }

    /** The channel {@code e} goes out on, created on first sight; null when the table is full. */
    ServedChannel find(Envelope e) {
        Key key = new Key(e.direction(), e.channel(), e.robotId(), e.kind(), RawChannel.of(e));
        ServedChannel c = byKey.get(key);
        return c != null ? c : create(key, e);
    }

    private synchronized ServedChannel create(Key key, Envelope e) {
        ServedChannel c = byKey.get(key);
        if (c != null) {
            return c;
        }
        if (byId.size() >= maxChannels) {
            refused.incrementAndGet();
            return null;
        }
        if (key.raw() != null) {
            c = new ServedChannel(nextId++, topics.of(e), key.raw().encoding(), "", "", "", key.raw(),
                    key.raw().metadata(topics.metadata(e)));
        } else {
            ChannelSchema schema = ChannelSchema.of(e, kinds);
            c = new ServedChannel(nextId++, topics.of(e), "protobuf", schema.schemaName(), schema.schemaBase64(),
                    "protobuf", schema, schema.metadata(topics.metadata(e)));
        }
        byKey.put(key, c);
        publish(c);
        return c;
    }

    /** A JSON channel (a console state); null when the table is full. */
    ServedChannel addJson(String topic, String schemaName, String jsonSchema) {
        return add(topic, "json", schemaName, jsonSchema, "jsonschema");
    }

    /** A protobuf channel of a standard Foxglove type ({@code schemaBase64}: its FileDescriptorSet); null when the table is full. */
    ServedChannel addProtobuf(String topic, String schemaName, String schemaBase64) {
        return add(topic, "protobuf", schemaName, schemaBase64, "protobuf");
    }

    private synchronized ServedChannel add(String topic, String encoding, String schemaName, String schema,
                                           String schemaEncoding) {
        if (byId.size() >= maxChannels) {
            refused.incrementAndGet();
            return null;
        }
        ServedChannel c = new ServedChannel(nextId++, topic, encoding, schemaName, schema, schemaEncoding, null, null);
        publish(c);
        return c;
    }

    private void publish(ServedChannel c) {
        byId.put(c.id(), c);
        for (Viewer v : viewers.all()) {
            v.advertise(List.of(c));
        }
    }

    /** Adds {@code v} to the viewers and tells it every channel known so far. */
    synchronized void welcome(Viewer v) {
        viewers.add(v);
        v.welcome(new ArrayList<>(byId.values()));
    }

    Optional<ServedChannel> byId(long id) {
        return id < 0 || id > Integer.MAX_VALUE ? Optional.empty() : Optional.ofNullable(byId.get((int) id));
    }

    int size() {
        return byId.size();
    }

    long refused() {
        return refused.get();
    }
}
