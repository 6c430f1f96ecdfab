package touchline.record;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Cuts and splices the records of an MCAP file's bytes, to craft the damaged and hostile
 * files the reader must survive (each a small file that once crashed or fooled it).
 */
final class McapSurgery {

    /** One record: opcode and its whole bytes (opcode, length, content). */
    record Rec(int opcode, byte[] bytes) { }

    private McapSurgery() {
    }

    static long u64(byte[] file, int at) {
        return ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN).getLong(at);
    }

    /** The footer's summary start. */
    static int summaryStart(byte[] file) {
        return (int) u64(file, file.length - 8 - 20 - 9 + 9);
    }

    /** Where the Data End record starts (the data section ends there). */
    static int dataEnd(byte[] file) {
        return summaryStart(file) - 13;
    }

    /** The records in {@code file[from, to)}. */
    static List<Rec> records(byte[] file, int from, int to) {
        List<Rec> out = new ArrayList<>();
        for (int at = from; at < to; ) {
            int length = 9 + (int) u64(file, at + 1);
            out.add(new Rec(file[at] & 0xFF, Arrays.copyOfRange(file, at, at + length)));
            at += length;
        }
        return out;
    }

    static byte[] record(int opcode, byte[] content) {
        ByteBuffer b = ByteBuffer.allocate(9 + content.length).order(ByteOrder.LITTLE_ENDIAN);
        b.put((byte) opcode).putLong(content.length).put(content);
        return b.array();
    }

    /** Little-endian fields: Long → 8 bytes, Integer → 4, Short → 2, Byte → 1, byte[] as is. */
    static byte[] le(Object... fields) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (Object f : fields) {
            ByteBuffer b = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN);
            if (f instanceof byte[] v) {
                out.writeBytes(v);
                continue;
            }
            if (f instanceof Long v) {
                b.putLong(v);
            } else if (f instanceof Integer v) {
                b.putInt(v);
            } else if (f instanceof Short v) {
                b.putShort(v);
            } else if (f instanceof Byte v) {
                b.put(v);
            } else {
                throw new IllegalArgumentException(f.toString());
            }
            out.write(b.array(), 0, b.position());
        }
        return out.toByteArray();
    }

    /** A footer (summary offset section 0, summary CRC 0 = not computed) and the closing magic. */
    static byte[] footer(long summaryStart) {
        return le(record(McapRecords.FOOTER, le(summaryStart, 0L, 0)), McapRecords.MAGIC);
    }

    static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }
}
