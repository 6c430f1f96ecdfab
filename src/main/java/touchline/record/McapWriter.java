package touchline.record;

import touchline.record.McapRecords.Bytes;

import java.io.Closeable;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;

/**
 * A small MCAP writer (https://mcap.dev/spec): chunked (uncompressed, zstd or lz4, see
 * {@link ChunkCompression}), indexed (message indexes after every chunk, their entries in
 * log-time order even when messages arrived out of order; chunk indexes, statistics,
 * metadata index and summary offsets in the summary). Schema and channel records go into the chunk that first uses them, so
 * every chunk is readable on its own after a crash. A chunk is written to the file when it
 * reaches {@code chunkBytes} or, through {@link #flushIfOlderThan}, when it is older than the
 * caller's limit, so a killed process loses at most that much. Not thread-safe: one writer
 * thread owns it. The open chunk's message indexes are kept by {@link MessageIndexes}.
 */
public final class McapWriter implements Closeable {

    /** Name of the metadata record that says which Touchline format wrote the file. */
    public static final String FORMAT_METADATA = "touchline.format";
    public static final int FORMAT_VERSION = 1;

    private record SchemaRecord(int id, String name, String encoding, byte[] data) { }

    private record ChannelRecord(int id, int schemaId, String topic, String encoding, Map<String, String> metadata) { }

    private record MetadataIndex(long offset, long length, String name) { }

    private final OutputStream out;
    private final int chunkBytes;
    private final ChunkCompression compression;
    private final CRC32 chunkCrc = new CRC32();
    private long position;

    private final List<SchemaRecord> schemas = new ArrayList<>();
    private final List<ChannelRecord> channels = new ArrayList<>();
    private final List<MetadataIndex> metadataIndexes = new ArrayList<>();
    private final Bytes chunkIndexes = new Bytes(4096);
    private int chunkCount;
    // per channel id: sequence numbers and message counts
    private int[] sequences = new int[16];
    private long[] messageCounts = new long[16];
    private final MessageIndexes messageIndexes = new MessageIndexes();

    private final Bytes chunk;
    private final Bytes scratch = new Bytes(1024);
    private final List<Integer> pendingDefinitions = new ArrayList<>();
    private long chunkStart = Long.MAX_VALUE;
    private long chunkEnd = Long.MIN_VALUE;
    private long chunkOpenedNanos;
    private boolean chunkHasContent;

    private long messageCount;
    private long firstTime = Long.MAX_VALUE;
    private long lastTime = Long.MIN_VALUE;
    private boolean closed;

    public McapWriter(Path file, int chunkBytes) throws IOException {
        this(Files.newOutputStream(file), chunkBytes, ChunkCompression.NONE);
    }

    public McapWriter(OutputStream out, int chunkBytes) throws IOException {
        this(out, chunkBytes, ChunkCompression.NONE);
    }

    /** {@code out} should be unbuffered (a file stream): every chunk is written whole. */
    public McapWriter(OutputStream out, int chunkBytes, ChunkCompression compression) throws IOException {
        this.out = out;
        this.chunkBytes = chunkBytes;
        this.compression = compression;
        this.chunk = new Bytes(chunkBytes + 64 * 1024);
        scratch.raw(McapRecords.MAGIC);
        int at = scratch.beginRecord(McapRecords.HEADER);
        scratch.string("touchline");
        scratch.string("touchline-record " + FORMAT_VERSION);
        scratch.endRecord(at);
        emit(scratch, true);
        addMetadata(FORMAT_METADATA, Map.of("version", Integer.toString(FORMAT_VERSION)));
    }

    /** Registers a schema (written with the first channel that uses it); returns its id (1..). */
    public int addSchema(String name, String encoding, byte[] data) {
        int id = schemas.size() + 1;
        schemas.add(new SchemaRecord(id, name, encoding, data));
        pendingDefinitions.add(-id);
        return id;
    }

    /** Registers a channel; schemaId 0 means "no schema". Returns its id (0..65535). */
    public int addChannel(int schemaId, String topic, String messageEncoding, Map<String, String> metadata) {
        int id = channels.size();
        if (id > 0xFFFF) {
            throw new IllegalStateException("an MCAP file holds at most 65536 channels");
        }
        channels.add(new ChannelRecord(id, schemaId, topic, messageEncoding, Map.copyOf(metadata)));
        pendingDefinitions.add(id);
        if (id >= sequences.length) {
            int n = sequences.length * 2;
            sequences = Arrays.copyOf(sequences, n);
            messageCounts = Arrays.copyOf(messageCounts, n);
            messageIndexes.ensureChannels(n);
        }
        return id;
    }

    public int channelCount() {
        return channels.size();
    }

    /** Writes a metadata record (name + string map) in the data section, outside chunks. */
    public void addMetadata(String name, Map<String, String> metadata) throws IOException {
        flushChunk();
        scratch.clear();
        int at = scratch.beginRecord(McapRecords.METADATA);
        scratch.string(name);
        writeMap(scratch, metadata);
        scratch.endRecord(at);
        metadataIndexes.add(new MetadataIndex(position, scratch.size, name));
        emit(scratch, true);
    }

    public void addMessage(int channelId, long logTimeNanos, long publishTimeNanos, byte[] data) throws IOException {
        addMessage(channelId, logTimeNanos, publishTimeNanos, data, 0, data.length);
    }

    public void addMessage(int channelId, long logTimeNanos, long publishTimeNanos, byte[] data, int off, int len)
            throws IOException {
        if (!pendingDefinitions.isEmpty()) {
            writeDefinitions();
        }
        if (!chunkHasContent) {
            chunkOpenedNanos = System.nanoTime();
            chunkHasContent = true;
        }
        int offset = chunk.size;
        chunk.u8(McapRecords.MESSAGE);
        chunk.u64(2 + 4 + 8 + 8 + len);
        chunk.u16(channelId);
        chunk.u32(sequences[channelId]++);
        chunk.u64(logTimeNanos);
        chunk.u64(publishTimeNanos);
        chunk.raw(data, off, len);
        messageIndexes.add(channelId, logTimeNanos, offset);
        chunkStart = Math.min(chunkStart, logTimeNanos);
        chunkEnd = Math.max(chunkEnd, logTimeNanos);
        firstTime = Math.min(firstTime, logTimeNanos);
        lastTime = Math.max(lastTime, logTimeNanos);
        messageCount++;
        messageCounts[channelId]++;
        if (chunk.size >= chunkBytes) {
            flushChunk();
        }
    }

    private void writeDefinitions() {
        for (int def : pendingDefinitions) {
            if (def < 0) {
                writeSchema(chunk, schemas.get(-def - 1));
            } else {
                writeChannel(chunk, channels.get(def));
            }
        }
        pendingDefinitions.clear();
        chunkHasContent = true;
    }

    /** Writes the open chunk if it is older than {@code maxAgeNanos}; true when it did. */
    public boolean flushIfOlderThan(long maxAgeNanos) throws IOException {
        if (chunkHasContent && System.nanoTime() - chunkOpenedNanos >= maxAgeNanos) {
            flushChunk();
            return true;
        }
        return false;
    }

    /** Bytes in the file so far plus the open chunk: what splitting by size looks at. */
    public long size() {
        return position + chunk.size;
    }

    public long messageCount() {
        return messageCount;
    }

    /** Writes the open chunk and its message indexes to the file. */
    public void flushChunk() throws IOException {
        if (!chunkHasContent) {
            return;
        }
        if (!pendingDefinitions.isEmpty()) {
            writeDefinitions();
        }
        long start = chunkStart == Long.MAX_VALUE ? 0 : chunkStart;
        long end = chunkEnd == Long.MIN_VALUE ? 0 : chunkEnd;
        chunkCrc.reset();
        chunkCrc.update(chunk.buf, 0, chunk.size);
        long uncompressedSize = chunk.size;
        byte[] records = compression.compress(chunk.buf, chunk.size);
        int recordsLength = compression == ChunkCompression.NONE ? chunk.size : records.length;
        scratch.clear();
        int at = scratch.beginRecord(McapRecords.CHUNK);
        scratch.u64(start);
        scratch.u64(end);
        scratch.u64(uncompressedSize);
        scratch.u32(chunkCrc.getValue());
        scratch.string(compression.mcapName());
        scratch.u64(recordsLength);
        long chunkOffset = position;
        long chunkLength = scratch.size + (long) recordsLength;
        scratch.putU64At(at, chunkLength - 9);
        emit(scratch, false);
        write(records, recordsLength);
        chunk.clear();

        scratch.clear();
        Map<Integer, Long> indexOffsets = messageIndexes.writeAndClear(scratch, chunkOffset + chunkLength);
        long indexLength = scratch.size;
        emit(scratch, true);

        int ci = chunkIndexes.beginRecord(McapRecords.CHUNK_INDEX);
        chunkIndexes.u64(start);
        chunkIndexes.u64(end);
        chunkIndexes.u64(chunkOffset);
        chunkIndexes.u64(chunkLength);
        int map = chunkIndexes.beginPrefixed32();
        for (Map.Entry<Integer, Long> e : indexOffsets.entrySet()) {
            chunkIndexes.u16(e.getKey());
            chunkIndexes.u64(e.getValue());
        }
        chunkIndexes.endPrefixed32(map);
        chunkIndexes.u64(indexLength);
        chunkIndexes.string(compression.mcapName());
        chunkIndexes.u64(recordsLength);
        chunkIndexes.u64(uncompressedSize);
        chunkIndexes.endRecord(ci);
        chunkCount++;

        chunkStart = Long.MAX_VALUE;
        chunkEnd = Long.MIN_VALUE;
        chunkHasContent = false;
    }

    private void write(byte[] b, int length) throws IOException {
        out.write(b, 0, length);
        position += length;
    }

    private void emit(Bytes b, boolean push) throws IOException {
        out.write(b.buf, 0, b.size);
        position += b.size;
        b.clear();
        if (push) {
            out.flush();
        }
    }

    private static void writeSchema(Bytes b, SchemaRecord s) {
        int at = b.beginRecord(McapRecords.SCHEMA);
        b.u16(s.id());
        b.string(s.name());
        b.string(s.encoding());
        b.u32(s.data().length);
        b.raw(s.data());
        b.endRecord(at);
    }

    private static void writeChannel(Bytes b, ChannelRecord c) {
        int at = b.beginRecord(McapRecords.CHANNEL);
        b.u16(c.id());
        b.u16(c.schemaId());
        b.string(c.topic());
        b.string(c.encoding());
        writeMap(b, new TreeMap<>(c.metadata()));
        b.endRecord(at);
    }

    private static void writeMap(Bytes b, Map<String, String> map) {
        int at = b.beginPrefixed32();
        for (Map.Entry<String, String> e : new TreeMap<>(map).entrySet()) {
            b.string(e.getKey());
            b.string(e.getValue());
        }
        b.endPrefixed32(at);
    }

    /** Writes the last chunk, the data end, the summary and the footer, then closes the file. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            flushChunk();
            scratch.clear();
            int at = scratch.beginRecord(McapRecords.DATA_END);
            // 0 = "not computed" (spec): every chunk carries its own CRC, which the reader checks;
            // a second pass over every byte cost the recording thread as much as a third of its work
            scratch.u32(0);
            scratch.endRecord(at);
            emit(scratch, false);

            long summaryStart = position;
            CRC32 summaryCrc = new CRC32();
            Bytes summary = new Bytes(chunkIndexes.size + 4096);
            List<long[]> groups = new ArrayList<>();
            int groupStart = summary.size;
            for (SchemaRecord s : schemas) {
                writeSchema(summary, s);
            }
            groups.add(new long[]{McapRecords.SCHEMA, summaryStart + groupStart, summary.size - groupStart});
            groupStart = summary.size;
            for (ChannelRecord c : channels) {
                writeChannel(summary, c);
            }
            groups.add(new long[]{McapRecords.CHANNEL, summaryStart + groupStart, summary.size - groupStart});
            groupStart = summary.size;
            summary.raw(chunkIndexes.buf, 0, chunkIndexes.size);
            groups.add(new long[]{McapRecords.CHUNK_INDEX, summaryStart + groupStart, summary.size - groupStart});
            groupStart = summary.size;
            for (MetadataIndex m : metadataIndexes) {
                int rec = summary.beginRecord(McapRecords.METADATA_INDEX);
                summary.u64(m.offset());
                summary.u64(m.length());
                summary.string(m.name());
                summary.endRecord(rec);
            }
            groups.add(new long[]{McapRecords.METADATA_INDEX, summaryStart + groupStart, summary.size - groupStart});
            groupStart = summary.size;
            int st = summary.beginRecord(McapRecords.STATISTICS);
            summary.u64(messageCount);
            summary.u16(schemas.size());
            summary.u32(channels.size());
            summary.u32(0);
            summary.u32(metadataIndexes.size());
            summary.u32(chunkCount);
            summary.u64(messageCount == 0 ? 0 : firstTime);
            summary.u64(messageCount == 0 ? 0 : lastTime);
            int map = summary.beginPrefixed32();
            for (int c = 0; c < channels.size(); c++) {
                summary.u16(c);
                summary.u64(messageCounts[c]);
            }
            summary.endPrefixed32(map);
            summary.endRecord(st);
            groups.add(new long[]{McapRecords.STATISTICS, summaryStart + groupStart, summary.size - groupStart});

            long summaryOffsetStart = summaryStart + summary.size;
            for (long[] g : groups) {
                if (g[2] == 0) {
                    continue;
                }
                int rec = summary.beginRecord(McapRecords.SUMMARY_OFFSET);
                summary.u8((int) g[0]);
                summary.u64(g[1]);
                summary.u64(g[2]);
                summary.endRecord(rec);
            }
            summary.u8(McapRecords.FOOTER);
            summary.u64(8 + 8 + 4);
            summary.u64(summaryStart);
            summary.u64(summaryOffsetStart);
            summaryCrc.update(summary.buf, 0, summary.size);
            summary.u32(summaryCrc.getValue());
            summary.raw(McapRecords.MAGIC);
            out.write(summary.buf, 0, summary.size);
            position += summary.size;
        } finally {
            out.close();
        }
    }
}
