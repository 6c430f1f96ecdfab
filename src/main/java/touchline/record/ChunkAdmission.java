package touchline.record;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static touchline.record.RecordFields.bytes;

/**
 * Which chunks of a recording are read: each chunk's header is read and checked, and its claimed
 * size weighed against the file's {@link ExpansionLimit} before anything is allocated for it.
 */
final class ChunkAdmission {

    // a compression name longer than this is none the reader knows
    private static final int MAX_COMPRESSION_NAME = 64;

    private final McapFile file;
    private final McapContents contents;
    private final CopyOnWriteArrayList<String> problems;
    private final ExpansionLimit limit;
    private int refused;

    ChunkAdmission(McapFile file, McapContents contents, ExpansionLimit limit) {
        this.file = file;
        this.contents = contents;
        this.problems = contents.problems;
        this.limit = limit;
    }

    /** Chunks not read because the file would expand beyond its limit. */
    int refused() {
        return refused;
    }

    /**
     * Reads every chunk's header and keeps the blocks whose records the expansion limit still
     * allows, in file order: a chunk's claimed size is weighed against the file and what is left
     * of the limit before anything is allocated for it. Chunks that cannot be read at all are
     * said here, once.
     */
    void admit() throws IOException {
        long allowed = limit.allowedBytes(file.size());
        long admitted = 0;
        long refusedBytes = 0;
        long firstRefused = -1;
        List<DataBlock> kept = new ArrayList<>();
        for (DataBlock b : contents.blocks) {
            DataBlock block = b.loose() ? b : withHeader(b);
            if (block == null) {
                continue;
            }
            long yields = block.loose() ? block.length() : block.chunk().yields();
            if (yields > allowed - admitted) {
                refused++;
                refusedBytes += yields;
                firstRefused = firstRefused < 0 ? block.offset() : firstRefused;
                continue;
            }
            admitted += yields;
            kept.add(block);
        }
        contents.blocks.clear();
        contents.blocks.addAll(kept);
        if (refused > 0) {
            problems.addIfAbsent(refused + " of " + (refused + kept.size()) + " chunks (from byte "
                    + firstRefused + " on, " + ExpansionLimit.size(refusedBytes) + " uncompressed) are not read: "
                    + limit.describe(file.size()) + ", and the chunks before them hold " + ExpansionLimit.size(admitted));
        }
    }

    /** {@code b} with its chunk header, or null (said) when there is no readable chunk there. */
    private DataBlock withHeader(DataBlock b) throws IOException {
        long end = b.offset() + Math.min(b.length(), file.size() - b.offset());
        int head = (int) Math.min(end - b.offset(), 9 + ChunkHeader.FIXED_BYTES + MAX_COMPRESSION_NAME);
        ByteBuffer h = ByteBuffer.wrap(file.read(b.offset(), head)).order(ByteOrder.LITTLE_ENDIAN);
        if (head == 0 || h.get(0) != McapRecords.CHUNK) {
            problems.addIfAbsent("the index points at byte " + b.offset() + ", where there is no chunk; skipped");
            return null;
        }
        if (head < 9 + ChunkHeader.FIXED_BYTES) {
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
        if (recordsLength < 0 || uncompressedSize < 0 || uncompressedSize > McapReader.MAX_CHUNK_BYTES) {
            problems.addIfAbsent("chunk at byte " + b.offset() + " declares impossible sizes (records "
                    + recordsLength + ", uncompressed " + uncompressedSize + " bytes); skipped");
            return null;
        }
        long recordsStart = b.offset() + h.position();
        boolean cut = recordsLength > end - recordsStart;
        long stored = Math.min(recordsLength, end - recordsStart);
        if (stored > McapReader.MAX_CHUNK_BYTES) {
            problems.addIfAbsent("chunk at byte " + b.offset() + " is larger than " + (McapReader.MAX_CHUNK_BYTES >> 20)
                    + " MB; skipped");
            return null;
        }
        if (cut && compression != ChunkCompression.NONE) {
            problems.addIfAbsent("the compressed chunk at byte " + b.offset() + " is cut off; its messages are lost");
            return null;
        }
        return new DataBlock(b.offset(), b.length(), b.startTime(), b.endTime(), false,
                new ChunkHeader(uncompressedSize, crc, compression, recordsStart, stored, cut));
    }
}
