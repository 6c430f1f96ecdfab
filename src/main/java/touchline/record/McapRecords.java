package touchline.record;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Record opcodes and the growable little-endian byte buffer the MCAP writer serialises
 * records into. MCAP (https://mcap.dev/spec) is little-endian throughout; strings and maps
 * carry a uint32 byte-length prefix, a record is opcode (uint8) + content length (uint64).
 */
final class McapRecords {

    static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

    static final int HEADER = 0x01;
    static final int FOOTER = 0x02;
    static final int SCHEMA = 0x03;
    static final int CHANNEL = 0x04;
    static final int MESSAGE = 0x05;
    static final int CHUNK = 0x06;
    static final int MESSAGE_INDEX = 0x07;
    static final int CHUNK_INDEX = 0x08;
    static final int ATTACHMENT = 0x09;
    static final int ATTACHMENT_INDEX = 0x0A;
    static final int STATISTICS = 0x0B;
    static final int METADATA = 0x0C;
    static final int METADATA_INDEX = 0x0D;
    static final int SUMMARY_OFFSET = 0x0E;
    static final int DATA_END = 0x0F;

    private McapRecords() {
    }

    /** A growable little-endian buffer; records are built in place to avoid copies. */
    static final class Bytes {
        // one store per field instead of a loop of byte stores: this runs several times per recorded message
        private static final java.lang.invoke.VarHandle U16 = java.lang.invoke.MethodHandles.byteArrayViewVarHandle(
                short[].class, java.nio.ByteOrder.LITTLE_ENDIAN);
        private static final java.lang.invoke.VarHandle U32 = java.lang.invoke.MethodHandles.byteArrayViewVarHandle(
                int[].class, java.nio.ByteOrder.LITTLE_ENDIAN);
        private static final java.lang.invoke.VarHandle U64 = java.lang.invoke.MethodHandles.byteArrayViewVarHandle(
                long[].class, java.nio.ByteOrder.LITTLE_ENDIAN);

        byte[] buf;
        int size;

        Bytes(int capacity) {
            buf = new byte[capacity];
        }

        void clear() {
            size = 0;
        }

        private void ensure(int more) {
            if (size + more > buf.length) {
                buf = Arrays.copyOf(buf, Math.max(buf.length * 2, size + more));
            }
        }

        void u8(int v) {
            ensure(1);
            buf[size++] = (byte) v;
        }

        void u16(int v) {
            ensure(2);
            U16.set(buf, size, (short) v);
            size += 2;
        }

        void u32(long v) {
            ensure(4);
            U32.set(buf, size, (int) v);
            size += 4;
        }

        void u64(long v) {
            ensure(8);
            U64.set(buf, size, v);
            size += 8;
        }

        void putU64At(int at, long v) {
            U64.set(buf, at, v);
        }

        void putU32At(int at, long v) {
            U32.set(buf, at, (int) v);
        }

        void raw(byte[] b, int off, int len) {
            ensure(len);
            System.arraycopy(b, off, buf, size, len);
            size += len;
        }

        void raw(byte[] b) {
            raw(b, 0, b.length);
        }

        void string(String s) {
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            u32(b.length);
            raw(b);
        }

        /** Starts a record; returns the position of its length field for {@link #endRecord}. */
        int beginRecord(int opcode) {
            u8(opcode);
            int at = size;
            u64(0);
            return at;
        }

        void endRecord(int lengthAt) {
            putU64At(lengthAt, size - lengthAt - 8);
        }

        /** Starts a uint32-length-prefixed map or array; returns the position of the prefix. */
        int beginPrefixed32() {
            int at = size;
            u32(0);
            return at;
        }

        void endPrefixed32(int at) {
            putU32At(at, size - at - 4);
        }
    }
}
