package touchline.record;

import touchline.record.McapReader.Attachment;
import touchline.record.McapReader.ChannelInfo;
import touchline.record.McapReader.Schema;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;

import static touchline.record.RecordFields.bytes;
import static touchline.record.RecordFields.map;
import static touchline.record.RecordFields.string;

/**
 * What a {@link McapReader} has learnt of its file: schemas, channels, metadata, attachments,
 * the blocks to read in file order, the statistics, and the problems found. Filled by the
 * {@link SummarySection} or a {@link LinearScan} when the file is opened; schemas, channels and
 * problems also grow while cursors read chunks (hence the concurrent collections).
 */
final class McapContents {

    final Map<Integer, Schema> schemas = new ConcurrentHashMap<>();
    final Map<Integer, ChannelInfo> channels = new ConcurrentHashMap<>();
    final Map<String, Map<String, String>> metadata = new ConcurrentHashMap<>();
    final CopyOnWriteArrayList<String> problems = new CopyOnWriteArrayList<>();
    final CopyOnWriteArrayList<Attachment> attachments = new CopyOnWriteArrayList<>();
    final Map<Integer, Long> statisticsPerChannel = new ConcurrentHashMap<>();
    final List<DataBlock> blocks = new ArrayList<>();
    boolean indexed;
    long messageCount = -1;
    long startTime = Long.MAX_VALUE;
    long endTime = Long.MIN_VALUE;

    void addSchema(ByteBuffer r) {
        int id = r.getShort() & 0xFFFF;
        String name = string(r);
        String encoding = string(r);
        byte[] data = bytes(r, r.getInt());
        schemas.put(id, new Schema(id, name, encoding, data));
    }

    void addChannel(ByteBuffer r) {
        int id = r.getShort() & 0xFFFF;
        int schemaId = r.getShort() & 0xFFFF;
        String topic = string(r);
        String encoding = string(r);
        channels.put(id, new ChannelInfo(id, schemaId, topic, encoding, map(r)));
    }

    /** Forgets what a damaged summary said (the problems stay), before the data is scanned instead. */
    void forgetSummary() {
        schemas.clear();
        channels.clear();
        blocks.clear();
        metadata.clear();
        attachments.clear();
        statisticsPerChannel.clear();
        messageCount = -1;
        startTime = Long.MAX_VALUE;
        endTime = Long.MIN_VALUE;
    }
}
