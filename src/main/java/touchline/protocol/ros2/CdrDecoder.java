package touchline.protocol.ros2;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;

/**
 * Decodes CDR (the ROS 2 wire format, XCDR1: a 4-byte encapsulation header, then the fields
 * in order, each primitive aligned to its size counted from after the header) by a
 * {@link MessageDefinition}. Little- and big-endian; the parameter-list encodings (PL_CDR) and
 * XCDR2 are refused with a reason. Every length is checked against the bytes left before
 * anything is allocated, so a hostile length costs nothing; messages nest at most
 * {@link DefinitionParser#MAX_NESTING} deep. Bounds of bounded strings and sequences are not
 * enforced (the bytes say how many; the check that matters is against what is left). A
 * {@code wstring} is a uint32 count of 4-byte characters (Fast-CDR's {@code wchar_t} on Linux).
 * Bytes after the last field (padding) are ignored.
 */
public final class CdrDecoder implements MessageDecoder {

    /** One compiled message type: its fields as the decoder walks them. */
    private static final class Plan {
        final MessageType type;
        final String[] names;
        final Field[] fields;
        final Plan[] nested;
        final long[] minElementSize;

        Plan(MessageType type) {
            this.type = type;
            this.names = type.fieldNames();
            this.fields = type.fields().toArray(new Field[0]);
            this.nested = new Plan[fields.length];
            this.minElementSize = new long[fields.length];
        }
    }

    private final String rootName;
    private final Plan root;

    public CdrDecoder(MessageDefinition definition) {
        this.rootName = definition.rootName();
        Map<String, Plan> plans = new HashMap<>();
        definition.types().forEach((name, type) -> plans.put(name, new Plan(type)));
        for (Plan p : plans.values()) {
            for (int i = 0; i < p.fields.length; i++) {
                Field f = p.fields[i];
                if (f.isMessage()) {
                    p.nested[i] = plans.get(f.typeName());
                }
                p.minElementSize[i] = f.isMessage() ? 1 : f.primitive().numeric() ? f.primitive().size() : 4;
            }
        }
        this.root = plans.get(rootName);
    }

    @Override
    public String typeName() {
        return rootName;
    }

    @Override
    public DecodeResult decode(byte[] data, int offset, int length) {
        if (offset < 0 || length < 0 || offset > data.length - length) {
            return new DecodeResult.Undecodable("no message: " + length + " bytes from " + offset + " of " + data.length);
        }
        if (length < 4) {
            return new DecodeResult.Undecodable("a CDR message of " + length + " bytes is shorter than its 4-byte header");
        }
        ByteOrder order;
        int kind = (data[offset] & 0xFF) << 8 | (data[offset + 1] & 0xFF);
        switch (kind) {
            case 0x0000 -> order = ByteOrder.BIG_ENDIAN;
            case 0x0001 -> order = ByteOrder.LITTLE_ENDIAN;
            case 0x0002, 0x0003 -> {
                return new DecodeResult.Undecodable("parameter-list CDR (PL_CDR_" + (kind == 2 ? "BE" : "LE")
                        + ") is not supported; ROS 2 messages are plain CDR");
            }
            default -> {
                return new DecodeResult.Undecodable(String.format("encapsulation %02X %02X is not CDR_BE (00 00) or"
                        + " CDR_LE (00 01)%s", data[offset], data[offset + 1], kind >= 6 && kind <= 11 ? " (XCDR2 is not supported)" : ""));
            }
        }
        Reader r = new Reader(data, offset + 4, offset + length, order);
        try {
            return new DecodeResult.Decoded(r.message(root, 0));
        } catch (Mismatch e) {
            return new DecodeResult.Undecodable(e.getMessage());
        }
    }

    /** Raised inside the decoder when the bytes do not fit; becomes {@link DecodeResult.Undecodable}. */
    private static final class Mismatch extends Exception {
        Mismatch(String message) {
            super(message, null, false, false);
        }
    }

    /** A cursor over one message. */
    private static final class Reader {
        private final byte[] data;
        private final ByteBuffer buf;
        private final int origin;
        private final int end;
        private int pos;

        Reader(byte[] data, int origin, int end, ByteOrder order) {
            this.data = data;
            this.buf = ByteBuffer.wrap(data).order(order);
            this.origin = origin;
            this.end = end;
            this.pos = origin;
        }

        RosMessage message(Plan plan, int depth) throws Mismatch {
            if (depth > DefinitionParser.MAX_NESTING) {
                throw new Mismatch(plan.type.name() + " nests deeper than " + DefinitionParser.MAX_NESTING + " levels");
            }
            Field[] fields = plan.fields;
            if (fields.length == 0) {
                need(1, plan.type.name(), "its placeholder byte");
                pos++;
                return new RosMessage(plan.type.name(), plan.type, plan.names, new Object[0]);
            }
            Object[] values = new Object[fields.length];
            for (int i = 0; i < fields.length; i++) {
                Field f = fields[i];
                if (f.shape() == Field.Shape.SINGLE) {
                    values[i] = f.isMessage() ? message(plan.nested[i], depth + 1) : single(f);
                } else {
                    int count;
                    if (f.shape() == Field.Shape.FIXED_ARRAY) {
                        count = f.bound();
                    } else {
                        align(4);
                        need(4, f.name(), "its length");
                        long n = Integer.toUnsignedLong(buf.getInt(pos));
                        pos += 4;
                        if (n > Integer.MAX_VALUE) {
                            throw new Mismatch(f.name() + " claims " + n + " elements; only " + (end - pos) + " bytes are left");
                        }
                        count = (int) n;
                    }
                    long least = (long) count * plan.minElementSize[i];
                    if (least > end - pos) {
                        throw new Mismatch(f.name() + " needs " + count + " elements (at least " + least + " bytes) but "
                                + (end - pos) + " bytes are left");
                    }
                    values[i] = f.isMessage() ? messages(plan.nested[i], count, depth) : array(f, count);
                }
            }
            return new RosMessage(plan.type.name(), plan.type, plan.names, values);
        }

        private RosMessage[] messages(Plan plan, int count, int depth) throws Mismatch {
            RosMessage[] out = new RosMessage[count];
            for (int k = 0; k < count; k++) {
                out[k] = message(plan, depth + 1);
            }
            return out;
        }

        private Object single(Field f) throws Mismatch {
            Primitive p = f.primitive();
            int size = p.size();
            if (size == 0) {
                return p == Primitive.STRING ? string(f) : wstring(f);
            }
            align(size);
            need(size, f.name(), p.word());
            int at = pos;
            pos += size;
            return switch (p) {
                case BOOL -> data[at] != 0;
                case INT8 -> (int) data[at];
                case UINT8, BYTE, CHAR -> data[at] & 0xFF;
                case INT16 -> (int) buf.getShort(at);
                case UINT16 -> buf.getShort(at) & 0xFFFF;
                case INT32 -> buf.getInt(at);
                case UINT32 -> buf.getInt(at) & 0xFFFFFFFFL;
                case INT64, UINT64 -> buf.getLong(at);
                case FLOAT32 -> buf.getFloat(at);
                case FLOAT64 -> buf.getDouble(at);
                default -> throw new IllegalStateException(p.toString());
            };
        }

        private Object array(Field f, int count) throws Mismatch {
            Primitive p = f.primitive();
            int size = p.size();
            if (size == 0) {
                String[] out = new String[count];
                for (int k = 0; k < count; k++) {
                    out[k] = p == Primitive.STRING ? string(f) : wstring(f);
                }
                return out;
            }
            if (count > 0) {
                align(size);
            }
            need((long) count * size, f.name(), count + " × " + p.word());
            int at = pos;
            pos += count * size;
            switch (p) {
                case BOOL -> {
                    boolean[] out = new boolean[count];
                    for (int k = 0; k < count; k++) {
                        out[k] = data[at + k] != 0;
                    }
                    return out;
                }
                case INT8, UINT8, BYTE, CHAR -> {
                    byte[] out = new byte[count];
                    System.arraycopy(data, at, out, 0, count);
                    return out;
                }
                case INT16, UINT16 -> {
                    short[] out = new short[count];
                    buf.slice(at, count * 2).order(buf.order()).asShortBuffer().get(out);
                    return out;
                }
                case INT32, UINT32 -> {
                    int[] out = new int[count];
                    buf.slice(at, count * 4).order(buf.order()).asIntBuffer().get(out);
                    return out;
                }
                case INT64, UINT64 -> {
                    long[] out = new long[count];
                    buf.slice(at, count * 8).order(buf.order()).asLongBuffer().get(out);
                    return out;
                }
                case FLOAT32 -> {
                    float[] out = new float[count];
                    buf.slice(at, count * 4).order(buf.order()).asFloatBuffer().get(out);
                    return out;
                }
                case FLOAT64 -> {
                    double[] out = new double[count];
                    buf.slice(at, count * 8).order(buf.order()).asDoubleBuffer().get(out);
                    return out;
                }
                default -> throw new IllegalStateException(p.toString());
            }
        }

        private String string(Field f) throws Mismatch {
            int n = length(f, 1);
            int at = pos;
            pos += n;
            // the length counts the terminating NUL; a writer that leaves it out (length 0) means ""
            int text = n > 0 && data[at + n - 1] == 0 ? n - 1 : n;
            return text == 0 ? "" : new String(data, at, text, StandardCharsets.UTF_8);
        }

        private String wstring(Field f) throws Mismatch {
            int n = length(f, 4);
            StringBuilder b = new StringBuilder(n);
            for (int k = 0; k < n; k++) {
                int c = buf.getInt(pos + 4 * k);
                if (c != 0) {
                    b.appendCodePoint(Character.isValidCodePoint(c) ? c : 0xFFFD);
                }
            }
            pos += 4 * n;
            return b.toString();
        }

        /** A uint32 length of elements of {@code unit} bytes, checked against what is left. */
        private int length(Field f, int unit) throws Mismatch {
            align(4);
            need(4, f.name(), "its length");
            long n = Integer.toUnsignedLong(buf.getInt(pos));
            pos += 4;
            if (n * unit > end - pos) {
                throw new Mismatch(f.name() + ": a string of " + n + (unit == 1 ? " bytes" : " characters") + " but "
                        + (end - pos) + " bytes are left");
            }
            return (int) n;
        }

        private void align(int size) {
            int rel = pos - origin;
            int mis = rel & (size - 1);
            if (mis != 0) {
                pos += size - mis;
            }
        }

        private void need(long bytes, String field, String what) throws Mismatch {
            if (bytes > end - pos) {
                throw new Mismatch("the message ends at byte " + (end - origin + 4) + " where " + field + " needs " + bytes
                        + " bytes for " + what + " (at byte " + Math.min(pos - origin + 4, end - origin + 4) + ")");
            }
        }
    }
}
