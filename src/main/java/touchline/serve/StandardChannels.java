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
 * <p>
 * Converting costs a few microseconds per envelope, so it runs on its own thread
 * ({@link StandardConversion}), converting each message once and serializing it once for all
 * viewers; after a robot's kind of message has been converted once (and its channels
 * advertised), it is converted again only while one of those channels has a subscriber. (A kind that later maps to another channel
 * too, e.g. a robot switching from raw to JPEG images, advertises it when next converted.)
 */
final class StandardChannels {

    static final int MAX_SOURCES = 4096;

    private final ChannelTable channels;
    private final StandardMessages convert = new StandardMessages();
    private final Map<String, ServedChannel> byTopic = new ConcurrentHashMap<>();
    private final Map<String, String> schemas = new ConcurrentHashMap<>();
    /** Per robot, direction, wire channel and kind: the channels its messages went to when last converted. */
    private final Map<Source, ServedChannel[]> madeBy = new ConcurrentHashMap<>();

    private record Source(int robotId, touchline.transport.Direction direction, touchline.transport.Channel channel,
                          String kind) {
    }

    StandardChannels(ChannelTable channels) {
        this.channels = channels;
    }

    /**
     * Whether {@code e} is worth converting: its kind was never converted (its channels are not
     * advertised yet), or one of the channels it went to has a subscriber. Cheap, for the
     * publishing thread, which then hands the envelope to {@link #accept} on another thread.
     */
    boolean wanted(Envelope e) {
        ServedChannel[] known = madeBy.get(new Source(e.robotId(), e.direction(), e.channel(), e.kind()));
        return known == null || subscribed(known);
    }

    /** Serves the standard messages {@code e} maps to, to the subscribers of their channels; one thread at a time. */
    void accept(Envelope e) {
        Source source = new Source(e.robotId(), e.direction(), e.channel(), e.kind());
        ServedChannel[] known = madeBy.get(source);
        if (known != null && !subscribed(known)) {
            return;
        }
        List<StandardMessage> made = convert.convert(e);
        ServedChannel[] used = new ServedChannel[made.size()];
        for (int i = 0; i < used.length; i++) {
            StandardMessage m = made.get(i);
            ServedChannel c = channel(m);
            used[i] = c;
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
        // Robot IDs and kinds come from the network: past MAX_SOURCES, new ones are simply converted every time.
        // (an envelope that made nothing, e.g. a status without a position, leaves what is known)
        if (used.length > 0 && (known != null ? !java.util.Arrays.equals(known, used) : madeBy.size() < MAX_SOURCES)) {
            madeBy.put(source, used);
        }
    }

    private static boolean subscribed(ServedChannel[] channels) {
        for (ServedChannel c : channels) {
            if (c != null && c.subscribers().length > 0) {
                return true;
            }
        }
        return false;
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
