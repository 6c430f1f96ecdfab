package touchline.record;

import java.io.Closeable;
import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.LongAdder;

/**
 * A small MCAP reader (https://mcap.dev/spec). With an intact summary it reads schemas,
 * channels and chunk indexes from it; without one (a recorder that was killed, a file cut
 * short) it scans the data section linearly up to the cut. Chunks may be uncompressed,
 * zstd or lz4 ({@link ChunkCompression}). A recording is input from outside (teams swap
 * logs), so every length is checked against what the file holds before anything is
 * allocated, each chunk is read once however often an index lists it, and chunks whose
 * CRC does not match, chunks of an unknown compression and records it cannot parse are
 * skipped and described in {@link #problems()}: bad input becomes a message, never an
 * exception, once the file is known to be MCAP at all. Cursors may be used from one thread
 * each.
 */
public final class McapReader implements Closeable {

    /** A schema record: for protobuf, name = full message name, data = a FileDescriptorSet. */
    public record Schema(int id, String name, String encoding, byte[] data) { }

    /** A channel record; schemaId 0 = no schema. */
    public record ChannelInfo(int id, int schemaId, String topic, String messageEncoding,
                              Map<String, String> metadata) { }

    /** One message record; times in nanoseconds. */
    public record McapMessage(int channelId, long sequence, long logTime, long publishTime, byte[] data) { }

    /** An attachment record (a file another tool stored in the recording): listed, its data not read. */
    public record Attachment(String name, String mediaType, long size, long logTime) { }

    /**
     * The largest chunk (uncompressed records) read: a chunk's header says how much to
     * allocate, and a damaged or hostile one must not make that the whole heap. Writers use
     * chunks of a few megabytes.
     */
    static final long MAX_CHUNK_BYTES = 256L << 20;

    private final Path path;
    private final McapFile file;
    private final ExpansionLimit limit;
    private final McapContents contents = new McapContents();
    private final CopyOnWriteArrayList<String> problems = contents.problems;
    private final List<DataBlock> blocks = contents.blocks;
    // messages per channel, counted once per block the first time any cursor loads it
    private final Map<Long, Boolean> countedBlocks = new ConcurrentHashMap<>();
    private final Map<Integer, LongAdder> channelMessages = new ConcurrentHashMap<>();
    private int refusedChunks;

    private McapReader(Path path, ExpansionLimit limit) throws IOException {
        this.path = path;
        this.limit = limit;
        this.file = new McapFile(path);
    }

    /**
     * Opens {@code file}. Throws {@link RecordingException} with a user-facing message when it
     * cannot be read or is not MCAP; everything else is reported through {@link #problems()}.
     */
    public static McapReader open(Path file) throws RecordingException {
        return open(file, ExpansionLimit.DEFAULT);
    }

    /**
     * Opens {@code file}, reading no more of its chunks than {@code limit} lets it expand to:
     * the chunks beyond are refused when it is opened, in file order, and said in {@link #problems()}.
     */
    public static McapReader open(Path file, ExpansionLimit limit) throws RecordingException {
        McapReader reader;
        try {
            reader = new McapReader(file, limit);
        } catch (IOException e) {
            throw new RecordingException("cannot open " + file + ": " + e.getMessage());
        }
        try {
            reader.load();
            return reader;
        } catch (IOException e) {
            reader.closeQuietly();
            throw new RecordingException("cannot read " + file + ": " + e.getMessage());
        } catch (RecordingException e) {
            reader.closeQuietly();
            throw e;
        }
    }

    private void load() throws IOException, RecordingException {
        if (file.size() == 0) {
            throw new RecordingException(path.getFileName() + " is empty (a recorder that was stopped before it"
                    + " wrote anything)");
        }
        byte[] head = file.read(0, (int) Math.min(8, file.size()));
        if (!Arrays.equals(head, McapRecords.MAGIC)) {
            throw new RecordingException(path.getFileName() + " is not an MCAP recording (it starts with "
                    + hex(head) + ", an MCAP file starts with 89 4D 43 41 50 30 0D 0A)");
        }
        if (!new SummarySection(file, contents).read()) {
            new LinearScan(file, contents).scan();
        } else if (blocks.isEmpty() && contents.messageCount != 0) {
            // an unchunked file (allowed by the spec; other tools write them): its messages
            // stand loose in the data section, and no index points to them
            contents.attachments.clear(); // the scan finds them again
            new LinearScan(file, contents).scan();
        }
        ChunkAdmission admission = new ChunkAdmission(file, contents, limit);
        admission.admit();
        refusedChunks = admission.refused();
        Map<String, String> format = contents.metadata.get(McapWriter.FORMAT_METADATA);
        if (format != null) {
            try {
                int version = Integer.parseInt(format.getOrDefault("version", "1"));
                if (version > McapWriter.FORMAT_VERSION) {
                    problems.addIfAbsent("recorded by a newer Touchline (format " + version + ", this one reads "
                            + McapWriter.FORMAT_VERSION + "); playing what this version understands");
                }
            } catch (NumberFormatException e) {
                problems.addIfAbsent("unreadable format version '" + format.get("version") + "'");
            }
        }
    }

    public Map<Integer, Schema> schemas() {
        return Collections.unmodifiableMap(contents.schemas);
    }

    public Map<Integer, ChannelInfo> channels() {
        return Collections.unmodifiableMap(contents.channels);
    }

    /** Metadata records by name (from the summary's metadata index, or found while scanning). */
    public Map<String, Map<String, String>> metadata() {
        return Collections.unmodifiableMap(contents.metadata);
    }

    /** The attachments the file lists (from the summary's attachment index, or found while scanning). */
    public List<Attachment> attachments() {
        return List.copyOf(contents.attachments);
    }

    /**
     * Messages of channel {@code channelId}: as the file's statistics say when they say, else
     * those in the blocks read so far (each block counted once, however many cursors read it).
     */
    public long messages(int channelId) {
        Long stated = contents.statisticsPerChannel.get(channelId);
        if (stated != null) {
            return stated;
        }
        LongAdder n = channelMessages.get(channelId);
        return n == null ? 0 : n.sum();
    }

    /** True when {@link #messages} is final: the statistics count channels, or every block has been read. */
    public boolean messageCountsFinal() {
        return !contents.statisticsPerChannel.isEmpty() || countedBlocks.size() >= blocks.size();
    }

    /** What could not be read, one user-facing sentence each; grows while cursors read chunks. */
    public List<String> problems() {
        return Collections.unmodifiableList(problems);
    }

    /** True when schemas, channels and chunks came from the summary (the file was closed cleanly). */
    public boolean indexed() {
        return contents.indexed;
    }

    /** Messages in the file according to its statistics, or -1 when it has none. */
    public long messageCount() {
        return contents.messageCount;
    }

    /** Log time of the first message (ns), or 0 when the file has none. */
    public long startTime() {
        return contents.startTime == Long.MAX_VALUE ? 0 : contents.startTime;
    }

    /** Log time of the last message (ns), or 0 when the file has none. */
    public long endTime() {
        return contents.endTime == Long.MIN_VALUE ? 0 : contents.endTime;
    }

    List<DataBlock> blocksForTest() {
        return List.copyOf(blocks);
    }

    /** Chunks not read because the file would expand beyond its {@link ExpansionLimit} (said in {@link #problems()}). */
    public int refusedChunks() {
        return refusedChunks;
    }

    public long chunkCount() {
        return blocks.stream().filter(b -> !b.loose()).count();
    }

    /** A cursor over messages in file order, starting at the first with log time >= {@code fromLogTime}. */
    public Cursor cursor(long fromLogTime) {
        int first = 0;
        while (first < blocks.size() && blocks.get(first).endTime() < fromLogTime) {
            first++;
        }
        return new Cursor(first, fromLogTime);
    }

    /** Reads messages block by block; {@link #next()} returns null at the end. */
    public final class Cursor {
        private int block;
        private final long from;
        private ByteBuffer records;
        private long recordsOffset;

        private Cursor(int block, long from) {
            this.block = block;
            this.from = from;
        }

        public McapMessage next() {
            while (true) {
                if (records == null || !records.hasRemaining()) {
                    if (block >= blocks.size()) {
                        return null;
                    }
                    DataBlock b = blocks.get(block++);
                    records = load(b);
                    if (countedBlocks.putIfAbsent(b.offset(), Boolean.TRUE) == null && records != null) {
                        countMessages(records.duplicate().order(ByteOrder.LITTLE_ENDIAN));
                    }
                    continue;
                }
                McapMessage m = nextRecord();
                if (m != null && Long.compareUnsigned(m.logTime(), from) >= 0) {
                    return m;
                }
            }
        }

        /** Adds the block's messages to the per-channel counts (record headers only). */
        private void countMessages(ByteBuffer r) {
            while (r.remaining() >= 9) {
                int op = r.get() & 0xFF;
                long len = r.getLong();
                if (len < 0 || len > r.remaining()) {
                    return;
                }
                if (op == McapRecords.MESSAGE && len >= 2) {
                    channelMessages.computeIfAbsent(r.getShort(r.position()) & 0xFFFF,
                            k -> new LongAdder()).increment();
                }
                r.position(r.position() + (int) len);
            }
        }

        private McapMessage nextRecord() {
            ByteBuffer r = records;
            int start = r.position();
            if (r.remaining() < 9) {
                r.position(r.limit());
                return null;
            }
            int op = r.get() & 0xFF;
            long len = r.getLong();
            if (len < 0 || len > r.remaining()) {
                problems.addIfAbsent("chunk at byte " + recordsOffset + ": a record at offset " + start
                        + " runs past the chunk's end; the rest of that chunk is skipped");
                r.position(r.limit());
                return null;
            }
            ByteBuffer rec = r.slice(r.position(), (int) len).order(ByteOrder.LITTLE_ENDIAN);
            r.position(r.position() + (int) len);
            try {
                switch (op) {
                    case McapRecords.MESSAGE -> {
                        int channel = rec.getShort() & 0xFFFF;
                        long seq = rec.getInt() & 0xFFFFFFFFL;
                        long logTime = rec.getLong();
                        long publishTime = rec.getLong();
                        byte[] data = new byte[rec.remaining()];
                        rec.get(data);
                        return new McapMessage(channel, seq, logTime, publishTime, data);
                    }
                    case McapRecords.SCHEMA -> contents.addSchema(rec);
                    case McapRecords.CHANNEL -> contents.addChannel(rec);
                    default -> { }
                }
            } catch (BufferUnderflowException | IllegalArgumentException e) {
                problems.addIfAbsent("chunk at byte " + recordsOffset + ": unreadable record at offset " + start + " skipped");
            }
            return null;
        }

        private ByteBuffer load(DataBlock b) {
            recordsOffset = b.offset();
            try {
                if (b.loose()) {
                    return ByteBuffer.wrap(file.read(b.offset(), (int) b.length())).order(ByteOrder.LITTLE_ENDIAN);
                }
                return b.chunk().records(file, b.offset(), problems);
            } catch (IOException | RuntimeException e) {
                // the checks when the file was opened should leave nothing to catch; a file from
                // outside still must not stop the replay if one was missed
                problems.addIfAbsent("chunk at byte " + b.offset() + " could not be read (" + e.getMessage()
                        + "); skipped");
                return null;
            }
        }
    }

    private static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(String.format("%02X ", x));
        }
        return s.toString().trim();
    }

    private void closeQuietly() {
        try {
            file.close();
        } catch (IOException ignored) {
            // nothing more to tell the user than the error already reported
        }
    }

    @Override
    public void close() {
        closeQuietly();
    }
}
