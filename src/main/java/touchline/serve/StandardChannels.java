package touchline.serve;

import touchline.record.SchemaSet;
import touchline.record.foxglove.StandardMessage;
import touchline.record.foxglove.StandardMessages;
import touchline.transport.Envelope;

import java.util.Base64;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The Foxglove standard channels served beside the raw ones ({@code /robot/3/log} as
 * {@code foxglove.Log}, {@code /robot/3/camera}, {@code /robot/3/regions}, {@code /field/scene},
 * {@code /tf}, {@code /nao/camera/image}; see {@link StandardMessages}), with the foxglove
 * schema's FileDescriptorSet, so the viewers' own Log, Image and 3D panels work on the live
 * stream as on an export. A channel is advertised the first time such a message is made.
 */
final class StandardChannels {

    private final ChannelTable channels;
    private final StandardMessages convert = new StandardMessages();
    private final Map<String, ServedChannel> byTopic = new ConcurrentHashMap<>();
    private final Map<String, String> schemas = new ConcurrentHashMap<>();

    StandardChannels(ChannelTable channels) {
        this.channels = channels;
    }

    /** Serves the standard messages {@code e} maps to, to the subscribers of their channels. */
    void accept(Envelope e) {
        List<StandardMessage> made = convert.convert(e);
        for (StandardMessage m : made) {
            ServedChannel c = channel(m);
            if (c == null) {
                continue; // the table is full (counted there)
            }
            Subscription[] subscribers = c.subscribers();
            if (subscribers.length == 0) {
                continue;
            }
            byte[] payload = m.message().toByteArray();
            for (Subscription s : subscribers) {
                s.viewer().offer(s, m.logTimeNanos(), payload);
            }
        }
    }

    private ServedChannel channel(StandardMessage m) {
        String key = m.topic() + "\n" + m.schemaName();
        ServedChannel c = byTopic.get(key);
        if (c != null) {
            return c;
        }
        synchronized (this) {
            c = byTopic.get(key);
            if (c == null) {
                String schema = schemas.computeIfAbsent(m.schemaName(), n -> Base64.getEncoder().encodeToString(
                        SchemaSet.descriptorSet(List.of(m.message().getDescriptorForType().getFile())).toByteArray()));
                c = channels.addProtobuf(m.topic(), m.schemaName(), schema);
                if (c != null) {
                    byTopic.put(key, c);
                }
            }
            return c;
        }
    }
}
