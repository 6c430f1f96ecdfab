package touchline.record.foxglove;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import touchline.protocol.MessageKinds;
import touchline.record.ChunkCompression;
import touchline.record.McapReader;
import touchline.record.McapWriter;
import touchline.record.Recording;
import touchline.record.SchemaSet;
import touchline.transport.Envelope;

import java.io.IOException;
import java.io.OutputStream;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * A recording copied for other tools: every recorded schema, channel, metadata record and
 * message as it was (so Touchline still replays the copy), and beside them the Foxglove
 * standard messages {@link StandardMessages} makes of each envelope, written right after the
 * message they come from (same log time).
 * <p>
 * The FUmanoids channels are recorded as the wrapper {@code fumanoid.Message}, whose content is
 * an extension that Foxglove's and Lichtblick's protobuf decoder shows only as a field named
 * {@code .fumanoid.status}, which no message path (Plot, Raw Messages) can name. So in the export
 * these recorded channels move under {@value #RECORDED_PREFIX} (their metadata, by which
 * Touchline replays them, unchanged), and their topics carry what the live server sends: the
 * extension's own type ({@code fumanoid.Status} on {@code /robot/3/status}), so a plot of
 * {@code /robot/3/status.batteryPercent} works on the export as on the live stream, with one layout.
 * Every added channel carries the metadata {@value Recording#STANDARD_CHANNEL} so a replay skips it quietly.
 */
public final class FoxgloveExport {

    /** What was written: messages copied, messages added per topic, and messages without a standard form. */
    public record Result(long copied, Map<String, Long> standardByTopic, long skipped) {

        public long standard() {
            return standardByTopic.values().stream().mapToLong(Long::longValue).sum();
        }
    }

    /** Where the recorded FUmanoids wrapper channels move to in the export. */
    public static final String RECORDED_PREFIX = "/touchline";
    private static final int CHUNK_BYTES = 512 * 1024;
    private static final String WRAPPER = "fumanoid.Message";

    private final MessageKinds kinds;

    /** {@code kinds}: the extensions known (the team's included: pass those the recording was opened with). */
    public FoxgloveExport(MessageKinds kinds) {
        this.kinds = kinds;
    }

    private final StandardMessages convert = new StandardMessages();
    private final Map<String, Integer> schemaIds = new HashMap<>();
    private final Map<String, Integer> channelIds = new HashMap<>();
    private final Map<String, Long> byTopic = new TreeMap<>();

    /** Writes the copy of {@code recording} to {@code out} (which this closes). */
    public Result write(Recording recording, OutputStream out, ChunkCompression compression) throws IOException {
        McapReader mcap = recording.mcap();
        long copied = 0;
        try (McapWriter w = new McapWriter(out, CHUNK_BYTES, compression)) {
            for (Map.Entry<String, Map<String, String>> m : mcap.metadata().entrySet()) {
                if (!m.getKey().equals(McapWriter.FORMAT_METADATA)) { // the writer adds its own
                    w.addMetadata(m.getKey(), m.getValue());
                }
            }
            Map<Integer, Integer> schemas = new HashMap<>();
            for (McapReader.Schema s : mcap.schemas().values()) {
                schemas.put(s.id(), w.addSchema(s.name(), s.encoding(), s.data()));
            }
            Map<Integer, Integer> channels = new HashMap<>();
            Map<Integer, String> wrapped = new HashMap<>(); // recorded wrapper channel -> its topic
            for (McapReader.ChannelInfo c : mcap.channels().values()) {
                McapReader.Schema schema = mcap.schemas().get(c.schemaId());
                String topic = c.topic();
                if (schema != null && schema.name().equals(WRAPPER) && c.messageEncoding().equals("protobuf")) {
                    wrapped.put(c.id(), topic);
                    topic = RECORDED_PREFIX + topic;
                }
                channels.put(c.id(), w.addChannel(c.schemaId() == 0 ? 0 : schemas.getOrDefault(c.schemaId(), 0),
                        topic, c.messageEncoding(), c.metadata()));
            }
            McapReader.Cursor cursor = mcap.cursor(0);
            for (McapReader.McapMessage m = cursor.next(); m != null; m = cursor.next()) {
                Integer channel = channels.get(m.channelId());
                if (channel == null) {
                    continue; // a message without a channel record: the reader has noted it
                }
                w.addMessage(channel, m.logTime(), m.publishTime(), m.data());
                copied++;
                Envelope e = recording.toEnvelope(m);
                String topic = wrapped.get(m.channelId());
                Message content = e == null || topic == null ? null : content(e);
                if (content != null) {
                    write(w, new StandardMessage(topic, m.logTime(), content));
                }
                if (e != null) {
                    for (StandardMessage s : convert.convert(e)) {
                        write(w, s);
                    }
                }
            }
        }
        return new Result(copied, Map.copyOf(byTopic), convert.skipped());
    }

    private void write(McapWriter w, StandardMessage s) throws IOException {
        w.addMessage(channel(w, s), s.logTimeNanos(), s.logTimeNanos(), s.message().toByteArray());
        byTopic.merge(s.topic(), 1L, Long::sum);
    }

    /** The extension a FUmanoids message carries, as its own type; null when it carries none we know. */
    private Message content(Envelope e) {
        if (!(e.message() instanceof touchline.proto.Fumanoid.Message m)) {
            return null;
        }
        FieldDescriptor ext = kinds.byName(e.kind()).orElse(null);
        if (ext == null || ext.getJavaType() != FieldDescriptor.JavaType.MESSAGE || ext.isRepeated() || !m.hasField(ext)) {
            return null;
        }
        return (Message) m.getField(ext);
    }

    private int channel(McapWriter w, StandardMessage s) {
        String key = s.topic() + "\n" + s.schemaName();
        Integer id = channelIds.get(key);
        if (id == null) {
            Descriptor type = s.message().getDescriptorForType();
            int schema = schemaIds.computeIfAbsent(s.schemaName(), n -> w.addSchema(n, "protobuf",
                    SchemaSet.descriptorSet(List.of(type.getFile())).toByteArray()));
            id = w.addChannel(schema, s.topic(), "protobuf", Map.of(Recording.STANDARD_CHANNEL, s.schemaName()));
            channelIds.put(key, id);
        }
        return id;
    }
}
