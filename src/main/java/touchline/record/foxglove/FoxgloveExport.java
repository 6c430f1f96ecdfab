package touchline.record.foxglove;

import com.google.protobuf.Descriptors.Descriptor;
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
 * message they come from (same log time). Their channels carry the metadata
 * {@value Recording#STANDARD_CHANNEL} so that a replay skips them quietly.
 */
public final class FoxgloveExport {

    /** What was written: messages copied, standard messages per topic, and messages without a standard form. */
    public record Result(long copied, Map<String, Long> standardByTopic, long skipped) {

        public long standard() {
            return standardByTopic.values().stream().mapToLong(Long::longValue).sum();
        }
    }

    private static final int CHUNK_BYTES = 512 * 1024;

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
            for (McapReader.ChannelInfo c : mcap.channels().values()) {
                channels.put(c.id(), w.addChannel(c.schemaId() == 0 ? 0 : schemas.getOrDefault(c.schemaId(), 0),
                        c.topic(), c.messageEncoding(), c.metadata()));
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
                if (e != null) {
                    for (StandardMessage s : convert.convert(e)) {
                        w.addMessage(channel(w, s), s.logTimeNanos(), s.logTimeNanos(), s.message().toByteArray());
                        byTopic.merge(s.topic(), 1L, Long::sum);
                    }
                }
            }
        }
        return new Result(copied, Map.copyOf(byTopic), convert.skipped());
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
