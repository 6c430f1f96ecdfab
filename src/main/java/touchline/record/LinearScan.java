package touchline.record;

import touchline.record.McapReader.Attachment;

import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.concurrent.CopyOnWriteArrayList;

import static touchline.record.RecordFields.map;
import static touchline.record.RecordFields.string;

/**
 * The data section of a recording without a usable summary (a recorder that was killed, a file
 * cut short, an unchunked file), read record by record into {@link McapContents} up to the cut:
 * schemas, channels and metadata as found, chunks and loose messages as blocks, attachments
 * listed. A record too large or too short to be what it says is skipped and said.
 */
final class LinearScan {

    // channel id, sequence, log time, publish time
    private static final int MESSAGE_HEADER_BYTES = 2 + 4 + 8 + 8;

    private final McapFile file;
    private final McapContents contents;
    private final CopyOnWriteArrayList<String> problems;

    LinearScan(McapFile file, McapContents contents) {
        this.file = file;
        this.contents = contents;
        this.problems = contents.problems;
    }

    void scan() throws IOException {
        long pos = 8;
        ByteBuffer header = ByteBuffer.allocate(9).order(ByteOrder.LITTLE_ENDIAN);
        while (pos < file.size()) {
            if (file.size() - pos < 9) {
                problems.addIfAbsent("the recording is cut off at byte " + file.size() + " inside a record header; "
                        + "everything before it plays");
                break;
            }
            header.clear();
            file.readFully(header, pos);
            header.flip();
            int op = header.get() & 0xFF;
            long len = header.getLong();
            if (len < 0 || len > file.size() - pos - 9) {
                if (op == McapRecords.CHUNK && len > 0) {
                    contents.blocks.add(new DataBlock(pos, file.size() - pos, Long.MIN_VALUE, Long.MAX_VALUE, false));
                    problems.addIfAbsent("the recording is cut off at byte " + file.size() + " inside its last chunk; "
                            + "the messages complete before the cut play (without CRC check)");
                } else {
                    problems.addIfAbsent("the recording is cut off at byte " + file.size() + " (a record of " + len
                            + " bytes starts at byte " + pos + "); everything before it plays");
                }
                break;
            }
            if (op == McapRecords.DATA_END || op == McapRecords.FOOTER) {
                break;
            }
            boolean read = op == McapRecords.SCHEMA || op == McapRecords.CHANNEL || op == McapRecords.METADATA
                    || op == McapRecords.CHUNK || op == McapRecords.MESSAGE;
            if (read && len > McapReader.MAX_CHUNK_BYTES) {
                problems.addIfAbsent("a record of " + len + " bytes at byte " + pos + " is larger than this reader"
                        + " accepts; skipped");
                pos += 9 + len;
                continue;
            }
            switch (op) {
                case McapRecords.SCHEMA, McapRecords.CHANNEL, McapRecords.METADATA -> {
                    ByteBuffer r = ByteBuffer.wrap(file.read(pos + 9, (int) len)).order(ByteOrder.LITTLE_ENDIAN);
                    try {
                        if (op == McapRecords.SCHEMA) {
                            contents.addSchema(r);
                        } else if (op == McapRecords.CHANNEL) {
                            contents.addChannel(r);
                        } else {
                            contents.metadata.put(string(r), map(r));
                        }
                    } catch (BufferUnderflowException | IllegalArgumentException e) {
                        problems.addIfAbsent("unreadable record at byte " + pos + " skipped");
                    }
                }
                case McapRecords.ATTACHMENT -> readAttachmentAt(pos, len);
                case McapRecords.CHUNK -> {
                    if (len < ChunkHeader.FIXED_BYTES) {
                        problems.addIfAbsent("a chunk at byte " + pos + " is too short to be one; skipped");
                    } else {
                        ByteBuffer r = ByteBuffer.wrap(file.read(pos + 9, 16)).order(ByteOrder.LITTLE_ENDIAN);
                        contents.blocks.add(new DataBlock(pos, 9 + len, r.getLong(), r.getLong(), false));
                    }
                }
                case McapRecords.MESSAGE -> {
                    if (len < MESSAGE_HEADER_BYTES) {
                        problems.addIfAbsent("a message at byte " + pos + " is too short to be one; skipped");
                    } else {
                        ByteBuffer r = ByteBuffer.wrap(file.read(pos + 9 + 6, 8)).order(ByteOrder.LITTLE_ENDIAN);
                        long t = r.getLong();
                        contents.blocks.add(new DataBlock(pos, 9 + len, t, t, true));
                    }
                }
                default -> { }
            }
            pos += 9 + len;
        }
        for (DataBlock b : contents.blocks) {
            if (b.startTime() != Long.MIN_VALUE) {
                contents.startTime = Math.min(contents.startTime, b.startTime());
                contents.endTime = Math.max(contents.endTime, b.endTime());
            }
        }
    }

    /** Lists the attachment record at {@code pos} (name, media type, data size) without reading its data. */
    private void readAttachmentAt(long pos, long len) throws IOException {
        ByteBuffer r = ByteBuffer.wrap(file.read(pos + 9, (int) Math.min(len, 64 * 1024))).order(ByteOrder.LITTLE_ENDIAN);
        try {
            long logTime = r.getLong();
            r.getLong();
            String name = string(r);
            String mediaType = string(r);
            contents.attachments.add(new Attachment(name, mediaType, r.getLong(), logTime));
        } catch (BufferUnderflowException | IllegalArgumentException e) {
            problems.addIfAbsent("unreadable attachment record at byte " + pos + " skipped");
        }
    }
}
