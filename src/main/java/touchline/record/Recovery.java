package touchline.record;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Turns a recording that did not finish (the recorder was killed, the power went, the disk
 * filled) into a finished MCAP file that every standard reader opens: everything
 * {@link McapReader} can still read (schemas, channels, metadata and every message of every
 * intact chunk) is written anew, with a summary and a footer. The recorder writes a chunk at
 * least every 0.8 s, so what is lost is at most the last second before the end.
 */
public final class Recovery {

    /** What the recovered file holds and what could not be saved, one user-facing sentence each. */
    public record Result(Path file, long messages, long channels, List<String> problems) { }

    private final McapReader damaged;
    private final Map<Integer, Integer> channelIds = new HashMap<>();
    private final Map<Integer, Integer> schemaIds = new HashMap<>();

    /** Reads {@code damaged}; throws with a user-facing message when it is not MCAP at all. */
    public Recovery(Path damaged) throws RecordingException {
        this(damaged, ExpansionLimit.DEFAULT);
    }

    /** Reads {@code damaged}, no more of it than {@code limit} lets it expand to (the rest is said, not written). */
    public Recovery(Path damaged, ExpansionLimit limit) throws RecordingException {
        this.damaged = McapReader.open(damaged, limit);
    }

    /** Writes the finished copy to {@code out} (never the damaged file itself, which stays as it was). */
    public Result writeTo(Path out) throws IOException {
        try (damaged; OutputStream stream = Files.newOutputStream(out); McapWriter writer =
                new McapWriter(stream, EnvelopeWriter.Options.defaults().chunkBytes(), ChunkCompression.NONE)) {
            for (Map.Entry<String, Map<String, String>> m : damaged.metadata().entrySet()) {
                if (!m.getKey().equals(McapWriter.FORMAT_METADATA)) {
                    writer.addMetadata(m.getKey(), m.getValue());
                }
            }
            long messages = 0;
            McapReader.Cursor cursor = damaged.cursor(0);
            for (McapReader.McapMessage m = cursor.next(); m != null; m = cursor.next()) {
                Integer channel = channelId(writer, m.channelId());
                if (channel != null) {
                    writer.addMessage(channel, m.logTime(), m.publishTime(), m.data());
                    messages++;
                }
            }
            return new Result(out, messages, channelIds.size(), List.copyOf(damaged.problems()));
        }
    }

    /** The id in the new file of the damaged file's channel {@code id}, defined there on first use. */
    private Integer channelId(McapWriter writer, int id) {
        Integer known = channelIds.get(id);
        if (known != null) {
            return known;
        }
        McapReader.ChannelInfo channel = damaged.channels().get(id);
        if (channel == null) {
            return null; // its definition was in the lost part; the reader has said so
        }
        int schema = 0;
        McapReader.Schema s = damaged.schemas().get(channel.schemaId());
        if (s != null) {
            schema = schemaIds.computeIfAbsent(s.id(), x -> writer.addSchema(s.name(), s.encoding(), s.data()));
        }
        int added = writer.addChannel(schema, channel.topic(), channel.messageEncoding(), channel.metadata());
        channelIds.put(id, added);
        return added;
    }
}
