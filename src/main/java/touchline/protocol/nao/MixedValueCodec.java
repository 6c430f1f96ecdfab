package touchline.protocol.nao;

import com.google.protobuf.ByteString;
import touchline.proto.Nao.MixedValue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * Converts NAOqi's ALValue wire form ({@link MixedValue}) to plain Java values and back.
 * Java side: {@link String}, {@link Long} (the wire int is an unsigned 32-bit value),
 * {@link Float}, {@code byte[]}, {@link Boolean} and {@link List} of those, nested. An empty
 * MixedValue (no field set) is indistinguishable from an empty array on the wire and decodes
 * to an empty list; {@code null} encodes to it. Both directions stop at a nesting depth limit
 * so a hostile or broken peer cannot make the console recurse without bound.
 */
public final class MixedValueCodec {

    /** Deep enough for any NAOqi value seen in practice (lists of lists of floats). */
    public static final int DEFAULT_MAX_DEPTH = 32;
    private static final long MAX_UINT32 = 0xFFFF_FFFFL;

    private final int maxDepth;

    public MixedValueCodec() {
        this(DEFAULT_MAX_DEPTH);
    }

    public MixedValueCodec(int maxDepth) {
        if (maxDepth < 1) {
            throw new IllegalArgumentException("maxDepth must be >= 1, was " + maxDepth);
        }
        this.maxDepth = maxDepth;
    }

    public int maxDepth() {
        return maxDepth;
    }

    /** Java value to wire value; throws {@link MixedValueException} for what cannot travel. */
    public MixedValue encode(Object value) {
        return encode(value, 1);
    }

    private MixedValue encode(Object value, int depth) {
        if (depth > maxDepth) {
            throw new MixedValueException("value nested deeper than " + maxDepth + " levels");
        }
        MixedValue.Builder b = MixedValue.newBuilder();
        if (value == null) {
            return b.build();
        } else if (value instanceof String s) {
            b.setString(s);
        } else if (value instanceof Boolean bool) {
            b.setBool(bool);
        } else if (value instanceof Float f) {
            b.setFloat(f);
        } else if (value instanceof Double d) {
            b.setFloat(d.floatValue());
        } else if (value instanceof Long || value instanceof Integer || value instanceof Short || value instanceof Byte) {
            long n = ((Number) value).longValue();
            if (n < 0 || n > MAX_UINT32) {
                throw new MixedValueException("int " + n + " cannot travel: the wire int is unsigned 32-bit"
                        + " (0.." + MAX_UINT32 + "); send it as a float instead");
            }
            b.setInt((int) n);
        } else if (value instanceof byte[] bytes) {
            b.setBinary(ByteString.copyFrom(bytes));
        } else if (value instanceof List<?> list) {
            for (Object element : list) {
                b.addArray(encode(element, depth + 1));
            }
        } else {
            throw new MixedValueException("cannot send a " + value.getClass().getSimpleName()
                    + " as a MixedValue (use String, int, float, bool, byte[] or a list of those)");
        }
        return b.build();
    }

    /** Encodes each element of a parameter list. */
    public List<MixedValue> encodeAll(List<?> values) {
        List<MixedValue> out = new ArrayList<>(values.size());
        for (Object v : values) {
            out.add(encode(v));
        }
        return out;
    }

    /** Wire value to Java value; throws {@link MixedValueException} for ambiguous or too deep values. */
    public Object decode(MixedValue value) {
        return decode(value, 1);
    }

    private Object decode(MixedValue v, int depth) {
        if (depth > maxDepth) {
            throw new MixedValueException("value nested deeper than " + maxDepth + " levels");
        }
        int set = (v.hasString() ? 1 : 0) + (v.hasInt() ? 1 : 0) + (v.hasFloat() ? 1 : 0)
                + (v.hasBinary() ? 1 : 0) + (v.hasBool() ? 1 : 0) + (v.getArrayCount() > 0 ? 1 : 0);
        if (set > 1) {
            throw new MixedValueException("MixedValue has " + set + " fields set; it must hold exactly one");
        }
        if (v.hasString()) {
            return v.getString();
        } else if (v.hasInt()) {
            return Integer.toUnsignedLong(v.getInt());
        } else if (v.hasFloat()) {
            return v.getFloat();
        } else if (v.hasBinary()) {
            return v.getBinary().toByteArray();
        } else if (v.hasBool()) {
            return v.getBool();
        }
        List<Object> list = new ArrayList<>(v.getArrayCount());
        for (MixedValue element : v.getArrayList()) {
            list.add(decode(element, depth + 1));
        }
        return Collections.unmodifiableList(list);
    }

    /** Human-readable text of a decoded value, as the CLI and the method browser show it. */
    public static String format(Object value) {
        StringBuilder sb = new StringBuilder();
        format(value, sb);
        return sb.toString();
    }

    private static void format(Object value, StringBuilder sb) {
        if (value instanceof String s) {
            sb.append('"').append(s.replace("\\", "\\\\").replace("\"", "\\\"")).append('"');
        } else if (value instanceof byte[] bytes) {
            sb.append("<binary ").append(bytes.length).append(" bytes>");
        } else if (value instanceof List<?> list) {
            sb.append('[');
            for (int i = 0; i < list.size(); i++) {
                if (i > 0) {
                    sb.append(", ");
                }
                format(list.get(i), sb);
            }
            sb.append(']');
        } else if (value instanceof Float f) {
            sb.append(f).append('f');
        } else {
            sb.append(value);
        }
    }
}
