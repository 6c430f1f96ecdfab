package touchline.record;

import touchline.record.McapReader.Attachment;

import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import static touchline.record.RecordFields.map;
import static touchline.record.RecordFields.string;

/**
 * The summary at the end of a cleanly closed recording, read into {@link McapContents}: schemas,
 * channels, chunk indexes (each chunk once, in file order), statistics, metadata and attachment
 * indexes. An entry pointing outside the data section is ignored and said; a damaged summary is
 * forgotten whole, and the reader scans the data instead ({@link LinearScan}).
 */
final class SummarySection {

    private final McapFile file;
    private final McapContents contents;
    private final CopyOnWriteArrayList<String> problems;

    SummarySection(McapFile file, McapContents contents) {
        this.file = file;
        this.contents = contents;
        this.problems = contents.problems;
    }

    /** Reads the summary; false (said in the problems when it is missing or damaged) when there is none to use. */
    boolean read() throws IOException {
        int tail = 1 + 8 + 20 + 8;
        if (file.size() < 8 + tail) {
            problems.addIfAbsent(cutMessage("no footer"));
            return false;
        }
        ByteBuffer t = ByteBuffer.wrap(file.read(file.size() - tail, tail)).order(ByteOrder.LITTLE_ENDIAN);
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
        long summaryEnd = summaryOffsetStart != 0 ? summaryOffsetStart : file.size() - tail;
        if (summaryStart < 8 || summaryEnd > file.size() - tail || summaryStart > summaryEnd) {
            problems.addIfAbsent("the summary offsets in the footer point outside the file; scanning the data instead");
            return false;
        }
        if (summaryEnd - summaryStart > McapReader.MAX_CHUNK_BYTES) {
            problems.addIfAbsent("the summary section is larger than " + (McapReader.MAX_CHUNK_BYTES >> 20)
                    + " MB; scanning the data instead");
            return false;
        }
        ByteBuffer s = ByteBuffer.wrap(file.read(summaryStart, (int) (summaryEnd - summaryStart)))
                .order(ByteOrder.LITTLE_ENDIAN);
        Set<Long> chunkOffsets = new HashSet<>();
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
                    case McapRecords.SCHEMA -> contents.addSchema(r);
                    case McapRecords.CHANNEL -> contents.addChannel(r);
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
                            contents.blocks.add(new DataBlock(offset, length, start, end, false));
                        }
                    }
                    case McapRecords.STATISTICS -> {
                        contents.messageCount = r.getLong();
                        r.position(r.position() + 2 + 4 + 4 + 4 + 4);
                        long start = r.getLong();
                        long end = r.getLong();
                        if (contents.messageCount > 0) {
                            contents.startTime = start;
                            contents.endTime = end;
                        }
                        int n = r.getInt();
                        if (n < 0 || n > r.remaining()) {
                            throw new BufferUnderflowException();
                        }
                        for (int i = 0; i < n / 10; i++) {
                            contents.statisticsPerChannel.put(r.getShort() & 0xFFFF, r.getLong());
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
                        contents.attachments.add(new Attachment(name, string(r), size, logTime));
                    }
                    default -> { }
                }
            }
        } catch (BufferUnderflowException | IllegalArgumentException | IndexOutOfBoundsException e) {
            problems.addIfAbsent("the summary section is damaged; scanning the data instead");
            contents.forgetSummary();
            return false;
        }
        // file order, whatever order the index lists them in: playback and seeking rely on it
        contents.blocks.sort(Comparator.comparingLong(DataBlock::offset));
        if (contents.startTime == Long.MAX_VALUE) {
            for (DataBlock b : contents.blocks) {
                contents.startTime = Math.min(contents.startTime, b.startTime());
                contents.endTime = Math.max(contents.endTime, b.endTime());
            }
        }
        contents.indexed = true;
        return true;
    }

    /** A record of {@code length} bytes at {@code offset} lies after the header, before {@code end}. */
    private static boolean insideDataSection(long offset, long length, long end) {
        return offset >= 8 && length >= 9 && offset < end && length <= end - offset;
    }

    private void readMetadataAt(long offset, long length) throws IOException {
        // subtraction, not offset + length: a huge length must not wrap around and pass
        if (offset < 8 || length < 9 || offset > file.size() || length > file.size() - offset || length > McapReader.MAX_CHUNK_BYTES) {
            problems.addIfAbsent("a metadata index entry points outside the file (" + offset + ", " + length
                    + " bytes); ignored");
            return;
        }
        ByteBuffer b = ByteBuffer.wrap(file.read(offset + 9, (int) length - 9)).order(ByteOrder.LITTLE_ENDIAN);
        String name = string(b);
        contents.metadata.put(name, map(b));
    }

    private String cutMessage(String what) {
        return "the recording is unfinished: it has " + what + " (it is still being written, or the recorder did not"
                + " finish: it was killed or the file was cut); playing what was written, scanning " + file.size()
                + " bytes";
    }
}
