package touchline.record;

import java.io.Closeable;
import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.zip.CRC32;

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
     * A chunk (or, for {@code loose}, a single message record outside any chunk) in file order;
     * {@code chunk} is its header once the file is open (null for a loose message).
     */
    record Block(long offset, long length, long startTime, long endTime, boolean loose, ChunkHeader chunk) {
        Block(long offset, long length, long startTime, long endTime, boolean loose) {
            this(offset, length, startTime, endTime, loose, null);
        }
    }

    /**
     * What a chunk record's header says: the size its records claim uncompressed, their CRC
     * and compression, and where the stored records lie in the file ({@code cut} when they
     * run past its end or the chunk's length).
     */
    record ChunkHeader(long uncompressedSize, long crc, ChunkCompression compression, long recordsStart,
                       long storedLength, boolean cut) {

        /** The bytes reading the chunk yields: what decompressing it claims, or what is stored. */
        long yields() {
            return compression == ChunkCompression.NONE ? storedLength : uncompressedSize;
        }
    }

    /**
     * The largest chunk (uncompressed records) read: a chunk's header says how much to
     * allocate, and a damaged or hostile one must not make that the whole heap. Writers use
     * chunks of a few megabytes.
     */
    static final long MAX_CHUNK_BYTES = 256L << 20;

    private final Path file;
    private final FileChannel in;
    private final long fileSize;
    private final ExpansionLimit limit;
    private int refusedChunks;
    private final Map<Integer, Schema> schemas = new ConcurrentHashMap<>();
    private final Map<Integer, ChannelInfo> channels = new ConcurrentHashMap<>();
    private final Map<String, Map<String, String>> metadata = new ConcurrentHashMap<>();
    private final CopyOnWriteArrayList<String> problems = new CopyOnWriteArrayList<>();
    private final CopyOnWriteArrayList<Attachment> attachments = new CopyOnWriteArrayList<>();
    // messages per channel, counted once per block the first time any cursor loads it
    private final Map<Long, Boolean> countedBlocks = new ConcurrentHashMap<>();
    private final Map<Integer, java.util.concurrent.atomic.LongAdder> channelMessages = new ConcurrentHashMap<>();
    private final Map<Integer, Long> statisticsPerChannel = new ConcurrentHashMap<>();
    private final List<Block> blocks = new ArrayList<>();
    private boolean indexed;
    private long messageCount = -1;
    private long startTime = Long.MAX_VALUE;
    private long endTime = Long.MIN_VALUE;

    private McapReader(Path file, ExpansionLimit limit) throws IOException {
        this.file = file;
        this.limit = limit;
        this.in = FileChannel.open(file, StandardOpenOption.READ);
        this.fileSize = in.size();
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
        if (fileSize == 0) {
            throw new RecordingException(file.getFileName() + " is empty (a recorder that was stopped before it"
                    + " wrote anything)");
        }
        byte[] head = read(0, (int) Math.min(8, fileSize));
        if (!Arrays.equals(head, McapRecords.MAGIC)) {
            throw new RecordingException(file.getFileName() + " is not an MCAP recording (it starts with "
                    + hex(head) + ", an MCAP file starts with 89 4D 43 41 50 30 0D 0A)");
        }
        if (!loadSummary()) {
            scanLinearly();
        } else if (blocks.isEmpty() && messageCount != 0) {
            // an unchunked file (allowed by the spec; other tools write them): its messages
            // stand loose in the data section, and no index points to them
            attachments.clear(); // the scan finds them again
            scanLinearly();
        }
        admitBlocks();
        Map<String, String> format = metadata.get(McapWriter.FORMAT_METADATA);
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

    private boolean loadSummary() throws IOException {
        int tail = 1 + 8 + 20 + 8;
        if (fileSize < 8 + tail) {
            problems.addIfAbsent(cutMessage("no footer"));
            return false;
        }
        ByteBuffer t = ByteBuffer.wrap(read(fileSize - tail, tail)).order(ByteOrder.LITTLE_ENDIAN);
        byte[] magic = Arrays.copyOfRange(t.array(), tail - 8, tail);
        if (t.get() != McapRecords.FOOTER || t.getLong() != 20 || !Arrays.equals(magic, McapRecords.MAGIC)) {
            problems.addIfAbsent(cutMessage("no footer"));
            return false;
        }
        long summaryStart = t.getLong();
        long summaryOffsetStart = t.getLong();
        if (summaryStart == 0) {
            return false;
        }
        long summaryEnd = summaryOffsetStart != 0 ? summaryOffsetStart : fileSize - tail;
        if (summaryStart < 8 || summaryEnd > fileSize - tail || summaryStart > summaryEnd) {
            problems.addIfAbsent("the summary offsets in the footer point outside the file; scanning the data instead");
            return false;
        }
        if (summaryEnd - summaryStart > MAX_CHUNK_BYTES) {
            problems.addIfAbsent("the summary section is larger than " + (MAX_CHUNK_BYTES >> 20)
                    + " MB; scanning the data instead");
            return false;
        }
        ByteBuffer s = ByteBuffer.wrap(read(summaryStart, (int) (summaryEnd - summaryStart)))
                .order(ByteOrder.LITTLE_ENDIAN);
        java.util.Set<Long> chunkOffsets = new java.util.HashSet<>();
        try {
            while (s.remaining() >= 9) {
                int op = s.get() & 0xFF;
                long len = s.getLong();
                if (len < 0 || len > s.remaining()) {
                    throw new BufferUnderflowException();
                }
                ByteBuffer r = s.slice(s.position(), (int) len).order(ByteOrder.LITTLE_ENDIAN);
                s.position(s.position() + (int) len);
                switch (op) {
                    case McapRecords.SCHEMA -> addSchema(r);
                    case McapRecords.CHANNEL -> addChannel(r);
                    case McapRecords.CHUNK_INDEX -> {
                        long start = r.getLong();
                        long end = r.getLong();
                        long offset = r.getLong();
                        long length = r.getLong();
                        if (!insideDataSection(offset, length, summaryStart)) {
                            problems.addIfAbsent("a chunk index points outside the data section (" + offset + ", "
                                    + length + " bytes); that entry is ignored");
                        } else if (!chunkOffsets.add(offset)) {
                            problems.addIfAbsent("the summary lists the chunk at byte " + offset
                                    + " more than once; it is read once");
                        } else {
                            blocks.add(new Block(offset, length, start, end, false));
                        }
                    }
                    case McapRecords.STATISTICS -> {
                        messageCount = r.getLong();
                        r.position(r.position() + 2 + 4 + 4 + 4 + 4);
                        long start = r.getLong();
                        long end = r.getLong();
                        if (messageCount > 0) {
                            startTime = start;
                            endTime = end;
                        }
                        int n = r.getInt();
                        if (n < 0 || n > r.remaining()) {
                            throw new BufferUnderflowException();
                        }
                        for (int i = 0; i < n / 10; i++) {
                            statisticsPerChannel.put(r.getShort() & 0xFFFF, r.getLong());
                        }
                    }
                    case McapRecords.METADATA_INDEX -> {
                        long offset = r.getLong();
                        long length = r.getLong();
                        readMetadataAt(offset, length);
                    }
                    case McapRecords.ATTACHMENT_INDEX -> {
                        r.getLong();
                        r.getLong();
                        long logTime = r.getLong();
                        r.getLong();
                        long size = r.getLong();
                        String name = string(r);
                        attachments.add(new Attachment(name, string(r), size, logTime));
                    }
                    default -> { }
                }
            }
        } catch (BufferUnderflowException | IllegalArgumentException | IndexOutOfBoundsException e) {
            problems.addIfAbsent("the summary section is damaged; scanning the data instead");
            schemas.clear();
            channels.clear();
            blocks.clear();
            metadata.clear();
            attachments.clear();
            statisticsPerChannel.clear();
            messageCount = -1;
            startTime = Long.MAX_VALUE;
            endTime = Long.MIN_VALUE;
            return false;
        }
        // file order, whatever order the index lists them in: playback and seeking rely on it
        blocks.sort(java.util.Comparator.comparingLong(Block::offset));
        if (startTime == Long.MAX_VALUE) {
            for (Block b : blocks) {
                startTime = Math.min(startTime, b.startTime());
                endTime = Math.max(endTime, b.endTime());
            }
        }
        indexed = true;
        return true;
    }

    /** A record of {@code length} bytes at {@code offset} lies after the header, before {@code end}. */
    private static boolean insideDataSection(long offset, long length, long end) {
        return offset >= 8 && length >= 9 && offset < end && length <= end - offset;
    }

    private void readMetadataAt(long offset, long length) throws IOException {
        // subtraction, not offset + length: a huge length must not wrap around and pass
        if (offset < 8 || length < 9 || offset > fileSize || length > fileSize - offset || length > MAX_CHUNK_BYTES) {
            problems.addIfAbsent("a metadata index entry points outside the file (" + offset + ", " + length
                    + " bytes); ignored");
            return;
        }
        ByteBuffer b = ByteBuffer.wrap(read(offset + 9, (int) length - 9)).order(ByteOrder.LITTLE_ENDIAN);
        String name = string(b);
        metadata.put(name, map(b));
    }

    /** Lists the attachment record at {@code pos} (name, media type, data size) without reading its data. */
    private void readAttachmentAt(long pos, long len) throws IOException {
        ByteBuffer r = ByteBuffer.wrap(read(pos + 9, (int) Math.min(len, 64 * 1024))).order(ByteOrder.LITTLE_ENDIAN);
        try {
            long logTime = r.getLong();
            r.getLong();
            String name = string(r);
            String mediaType = string(r);
            attachments.add(new Attachment(name, mediaType, r.getLong(), logTime));
        } catch (BufferUnderflowException | IllegalArgumentException e) {
            problems.addIfAbsent("unreadable attachment record at byte " + pos + " skipped");
        }
    }

    private String cutMessage(String what) {
        return "the recording is unfinished: it has " + what + " (it is still being written, or the recorder did not"
                + " finish: it was killed or the file was cut); playing what was written, scanning " + fileSize
                + " bytes";
    }

    private void scanLinearly() throws IOException {
        long pos = 8;
        ByteBuffer header = ByteBuffer.allocate(9).order(ByteOrder.LITTLE_ENDIAN);
        while (pos < fileSize) {
            if (fileSize - pos < 9) {
                problems.addIfAbsent("the recording is cut off at byte " + fileSize + " inside a record header; "
                        + "everything before it plays");
                break;
            }
            header.clear();
            readFully(header, pos);
            header.flip();
            int op = header.get() & 0xFF;
            long len = header.getLong();
            if (len < 0 || len > fileSize - pos - 9) {
                if (op == McapRecords.CHUNK && len > 0) {
                    blocks.add(new Block(pos, fileSize - pos, Long.MIN_VALUE, Long.MAX_VALUE, false));
                    problems.addIfAbsent("the recording is cut off at byte " + fileSize + " inside its last chunk; "
                            + "the messages complete before the cut play (without CRC check)");
                } else {
                    problems.addIfAbsent("the recording is cut off at byte " + fileSize + " (a record of " + len
                            + " bytes starts at byte " + pos + "); everything before it plays");
                }
                break;
            }
            if (op == McapRecords.DATA_END || op == McapRecords.FOOTER) {
                break;
            }
            boolean read = op == McapRecords.SCHEMA || op == McapRecords.CHANNEL || op == McapRecords.METADATA
                    || op == McapRecords.CHUNK || op == McapRecords.MESSAGE;
            if (read && len > MAX_CHUNK_BYTES) {
                problems.addIfAbsent("a record of " + len + " bytes at byte " + pos + " is larger than this reader"
                        + " accepts; skipped");
                pos += 9 + len;
                continue;
            }
            switch (op) {
                case McapRecords.SCHEMA, McapRecords.CHANNEL, McapRecords.METADATA -> {
                    ByteBuffer r = ByteBuffer.wrap(read(pos + 9, (int) len)).order(ByteOrder.LITTLE_ENDIAN);
                    try {
                        if (op == McapRecords.SCHEMA) {
                            addSchema(r);
                        } else if (op == McapRecords.CHANNEL) {
                            addChannel(r);
                        } else {
                            metadata.put(string(r), map(r));
                        }
                    } catch (BufferUnderflowException | IllegalArgumentException e) {
                        problems.addIfAbsent("unreadable record at byte " + pos + " skipped");
                    }
                }
                case McapRecords.ATTACHMENT -> readAttachmentAt(pos, len);
                case McapRecords.CHUNK -> {
                    if (len < CHUNK_HEADER_BYTES) {
                        problems.addIfAbsent("a chunk at byte " + pos + " is too short to be one; skipped");
                    } else {
                        ByteBuffer r = ByteBuffer.wrap(read(pos + 9, 16)).order(ByteOrder.LITTLE_ENDIAN);
                        blocks.add(new Block(pos, 9 + len, r.getLong(), r.getLong(), false));
                    }
                }
                case McapRecords.MESSAGE -> {
                    if (len < MESSAGE_HEADER_BYTES) {
                        problems.addIfAbsent("a message at byte " + pos + " is too short to be one; skipped");
                    } else {
                        ByteBuffer r = ByteBuffer.wrap(read(pos + 9 + 6, 8)).order(ByteOrder.LITTLE_ENDIAN);
                        long t = r.getLong();
                        blocks.add(new Block(pos, 9 + len, t, t, true));
                    }
                }
                default -> { }
            }
            pos += 9 + len;
        }
        for (Block b : blocks) {
            if (b.startTime() != Long.MIN_VALUE) {
                startTime = Math.min(startTime, b.startTime());
                endTime = Math.max(endTime, b.endTime());
            }
        }
    }

    /**
     * Reads every chunk's header and keeps the blocks whose records the expansion limit still
     * allows, in file order: a chunk's claimed size is weighed against the file and what is left
     * of the limit before anything is allocated for it. Chunks that cannot be read at all are
     * said here, once.
     */
    private void admitBlocks() throws IOException {
        long allowed = limit.allowedBytes(fileSize);
        long admitted = 0;
        long refusedBytes = 0;
        long firstRefused = -1;
        List<Block> kept = new ArrayList<>();
        for (Block b : blocks) {
            Block block = b.loose() ? b : withHeader(b);
            if (block == null) {
                continue;
            }
            long yields = block.loose() ? block.length() : block.chunk().yields();
            if (yields > allowed - admitted) {
                refusedChunks++;
                refusedBytes += yields;
                firstRefused = firstRefused < 0 ? block.offset() : firstRefused;
                continue;
            }
            admitted += yields;
            kept.add(block);
        }
        blocks.clear();
        blocks.addAll(kept);
        if (refusedChunks > 0) {
            problems.addIfAbsent(refusedChunks + " of " + (refusedChunks + kept.size()) + " chunks (from byte "
                    + firstRefused + " on, " + ExpansionLimit.size(refusedBytes) + " uncompressed) are not read: "
                    + limit.describe(fileSize) + ", and the chunks before them hold " + ExpansionLimit.size(admitted));
        }
    }

    /** {@code b} with its chunk header, or null (said) when there is no readable chunk there. */
    private Block withHeader(Block b) throws IOException {
        long end = b.offset() + Math.min(b.length(), fileSize - b.offset());
        int head = (int) Math.min(end - b.offset(), 9 + CHUNK_HEADER_BYTES + MAX_COMPRESSION_NAME);
        ByteBuffer h = ByteBuffer.wrap(read(b.offset(), head)).order(ByteOrder.LITTLE_ENDIAN);
        if (head == 0 || h.get(0) != McapRecords.CHUNK) {
            problems.addIfAbsent("the index points at byte " + b.offset() + ", where there is no chunk; skipped");
            return null;
        }
        if (head < 9 + CHUNK_HEADER_BYTES) {
            problems.addIfAbsent("the chunk at byte " + b.offset() + " is cut off inside its header; skipped");
            return null;
        }
        h.position(9 + 16);
        long uncompressedSize = h.getLong();
        long crc = h.getInt() & 0xFFFFFFFFL;
        int nameLength = h.getInt();
        if (nameLength < 0 || nameLength > h.remaining() - 8) {
            problems.addIfAbsent("chunk at byte " + b.offset() + " names a compression of " + nameLength
                    + " bytes, which this reader does not know (it reads zstd and lz4); its messages are skipped");
            return null;
        }
        String name = new String(bytes(h, nameLength), StandardCharsets.UTF_8);
        long recordsLength = h.getLong();
        ChunkCompression compression = ChunkCompression.ofMcapName(name).orElse(null);
        if (compression == null) {
            problems.addIfAbsent("chunk at byte " + b.offset() + " is compressed with '" + name
                    + "', which this reader does not know (it reads zstd and lz4); its messages are skipped");
            return null;
        }
        if (recordsLength < 0 || uncompressedSize < 0 || uncompressedSize > MAX_CHUNK_BYTES) {
            problems.addIfAbsent("chunk at byte " + b.offset() + " declares impossible sizes (records "
                    + recordsLength + ", uncompressed " + uncompressedSize + " bytes); skipped");
            return null;
        }
        long recordsStart = b.offset() + h.position();
        boolean cut = recordsLength > end - recordsStart;
        long stored = Math.min(recordsLength, end - recordsStart);
        if (stored > MAX_CHUNK_BYTES) {
            problems.addIfAbsent("chunk at byte " + b.offset() + " is larger than " + (MAX_CHUNK_BYTES >> 20)
                    + " MB; skipped");
            return null;
        }
        if (cut && compression != ChunkCompression.NONE) {
            problems.addIfAbsent("the compressed chunk at byte " + b.offset() + " is cut off; its messages are lost");
            return null;
        }
        return new Block(b.offset(), b.length(), b.startTime(), b.endTime(), false,
                new ChunkHeader(uncompressedSize, crc, compression, recordsStart, stored, cut));
    }

    // a compression name longer than this is none the reader knows
    private static final int MAX_COMPRESSION_NAME = 64;

    // start, end, uncompressed size, CRC, compression string length, records length
    private static final int CHUNK_HEADER_BYTES = 8 + 8 + 8 + 4 + 4 + 8;
    // channel id, sequence, log time, publish time
    private static final int MESSAGE_HEADER_BYTES = 2 + 4 + 8 + 8;

    private void addSchema(ByteBuffer r) {
        int id = r.getShort() & 0xFFFF;
        String name = string(r);
        String encoding = string(r);
        byte[] data = bytes(r, r.getInt());
        schemas.put(id, new Schema(id, name, encoding, data));
    }

    private void addChannel(ByteBuffer r) {
        int id = r.getShort() & 0xFFFF;
        int schemaId = r.getShort() & 0xFFFF;
        String topic = string(r);
        String encoding = string(r);
        channels.put(id, new ChannelInfo(id, schemaId, topic, encoding, map(r)));
    }

    private static String string(ByteBuffer r) {
        return new String(bytes(r, r.getInt()), StandardCharsets.UTF_8);
    }

    private static byte[] bytes(ByteBuffer r, long n) {
        if (n < 0 || n > r.remaining()) {
            throw new IllegalArgumentException("length " + n + " exceeds the record");
        }
        byte[] b = new byte[(int) n];
        r.get(b);
        return b;
    }

    private static Map<String, String> map(ByteBuffer r) {
        int n = r.getInt();
        if (n < 0 || n > r.remaining()) {
            throw new IllegalArgumentException("map length " + n + " exceeds the record");
        }
        ByteBuffer m = r.slice(r.position(), n).order(ByteOrder.LITTLE_ENDIAN);
        r.position(r.position() + n);
        Map<String, String> out = new LinkedHashMap<>();
        while (m.hasRemaining()) {
            out.put(string(m), string(m));
        }
        return Collections.unmodifiableMap(out);
    }

    private byte[] read(long pos, int n) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(n);
        readFully(b, pos);
        return b.array();
    }

    private void readFully(ByteBuffer b, long pos) throws IOException {
        while (b.hasRemaining()) {
            int r = in.read(b, pos + b.position());
            if (r < 0) {
                throw new IOException("unexpected end of file at byte " + (pos + b.position()));
            }
        }
    }

    public Map<Integer, Schema> schemas() {
        return Collections.unmodifiableMap(schemas);
    }

    public Map<Integer, ChannelInfo> channels() {
        return Collections.unmodifiableMap(channels);
    }

    /** Metadata records by name (from the summary's metadata index, or found while scanning). */
    public Map<String, Map<String, String>> metadata() {
        return Collections.unmodifiableMap(metadata);
    }

    /** The attachments the file lists (from the summary's attachment index, or found while scanning). */
    public List<Attachment> attachments() {
        return List.copyOf(attachments);
    }

    /**
     * Messages of channel {@code channelId}: as the file's statistics say when they say, else
     * those in the blocks read so far (each block counted once, however many cursors read it).
     */
    public long messages(int channelId) {
        Long stated = statisticsPerChannel.get(channelId);
        if (stated != null) {
            return stated;
        }
        java.util.concurrent.atomic.LongAdder n = channelMessages.get(channelId);
        return n == null ? 0 : n.sum();
    }

    /** True when {@link #messages} is final: the statistics count channels, or every block has been read. */
    public boolean messageCountsFinal() {
        return !statisticsPerChannel.isEmpty() || countedBlocks.size() >= blocks.size();
    }

    /** What could not be read, one user-facing sentence each; grows while cursors read chunks. */
    public List<String> problems() {
        return Collections.unmodifiableList(problems);
    }

    /** True when schemas, channels and chunks came from the summary (the file was closed cleanly). */
    public boolean indexed() {
        return indexed;
    }

    /** Messages in the file according to its statistics, or -1 when it has none. */
    public long messageCount() {
        return messageCount;
    }

    /** Log time of the first message (ns), or 0 when the file has none. */
    public long startTime() {
        return startTime == Long.MAX_VALUE ? 0 : startTime;
    }

    /** Log time of the last message (ns), or 0 when the file has none. */
    public long endTime() {
        return endTime == Long.MIN_VALUE ? 0 : endTime;
    }

    List<Block> blocksForTest() {
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
                    Block b = blocks.get(block++);
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
                            k -> new java.util.concurrent.atomic.LongAdder()).increment();
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
                    case McapRecords.SCHEMA -> addSchema(rec);
                    case McapRecords.CHANNEL -> addChannel(rec);
                    default -> { }
                }
            } catch (BufferUnderflowException | IllegalArgumentException e) {
                problems.addIfAbsent("chunk at byte " + recordsOffset + ": unreadable record at offset " + start + " skipped");
            }
            return null;
        }

        private ByteBuffer load(Block b) {
            recordsOffset = b.offset();
            try {
                if (b.loose()) {
                    return ByteBuffer.wrap(read(b.offset(), (int) b.length())).order(ByteOrder.LITTLE_ENDIAN);
                }
                return records(b.offset(), b.chunk());
            } catch (IOException | RuntimeException e) {
                // the checks when the file was opened should leave nothing to catch; a file from
                // outside still must not stop the replay if one was missed
                problems.addIfAbsent("chunk at byte " + b.offset() + " could not be read (" + e.getMessage()
                        + "); skipped");
                return null;
            }
        }

        private ByteBuffer records(long offset, ChunkHeader chunk) throws IOException {
            byte[] stored = read(chunk.recordsStart(), (int) chunk.storedLength());
            ByteBuffer records;
            try {
                records = ByteBuffer.wrap(chunk.compression().decompress(stored, (int) chunk.uncompressedSize()));
            } catch (IOException e) {
                problems.addIfAbsent("chunk at byte " + offset + " is damaged: " + e.getMessage()
                        + "; its messages are skipped, the rest plays");
                return null;
            }
            records.order(ByteOrder.LITTLE_ENDIAN);
            if (!chunk.cut() && (chunk.crc() != 0 || chunk.uncompressedSize() != records.remaining())) {
                CRC32 check = new CRC32();
                check.update(records.duplicate());
                if ((chunk.crc() != 0 && check.getValue() != chunk.crc())
                        || chunk.uncompressedSize() != records.remaining()) {
                    problems.addIfAbsent("chunk at byte " + offset + " is corrupt (CRC "
                            + Long.toHexString(check.getValue()) + ", expected " + Long.toHexString(chunk.crc()) + ", "
                            + records.remaining() + " of " + chunk.uncompressedSize() + " bytes); its messages are"
                            + " skipped, the rest plays");
                    return null;
                }
            }
            return records;
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
            in.close();
        } catch (IOException ignored) {
            // nothing more to tell the user than the error already reported
        }
    }

    @Override
    public void close() {
        closeQuietly();
    }
}
