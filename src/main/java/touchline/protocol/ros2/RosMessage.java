package touchline.protocol.ros2;

import java.util.ArrayList;
import java.util.List;

/**
 * A message decoded by its definition (ROS 2 CDR) or from JSON: its type name and its fields in
 * order, each a plain Java value. The tree views, plots, CSV and the consoles read; it holds no
 * reference to the bytes it came from. Values:
 * <ul>
 * <li>{@code bool} → Boolean; {@code int8 … int32}, {@code uint8}, {@code uint16}, {@code byte},
 *     {@code char} → Integer; {@code uint32}, {@code int64}, {@code uint64} → Long ({@code uint64}
 *     keeps its 64 bits; {@link #number} reads it unsigned); {@code float32} → Float;
 *     {@code float64} → Double; strings → String; a nested message → RosMessage.</li>
 * <li>Arrays and sequences → a Java array of the element: {@code boolean[]}, {@code byte[]}
 *     (int8, uint8, byte, char: an image's data stays one array), {@code short[]} (16 bit),
 *     {@code int[]} (32 bit), {@code long[]} (64 bit), {@code float[]}, {@code double[]},
 *     {@code String[]}, {@code RosMessage[]}.</li>
 * <li>From JSON (no definition, {@link #type()} null): numbers → Long or Double, arrays →
 *     {@code Object[]}, objects → RosMessage, JSON null → null.</li>
 * </ul>
 * Field paths ({@link #at}, {@link #forEachNumber}) are dotted with indices:
 * {@code pose.position.x}, {@code position[3]}, {@code markers[0].scale.x}. Immutable once made.
 */
public final class RosMessage {

    /**
     * Arrays longer than this enumerate only their first elements as numbers ({@link #forEachNumber}):
     * a laser scan's ranges are many numbers, not many plots. 8-bit arrays (image data, blobs)
     * enumerate none, as protobuf bytes fields export none.
     */
    public static final int MAX_ENUMERATED_ELEMENTS = 256;

    /** Nested messages deeper than this are not enumerated or rendered (a hostile JSON document nests deeper). */
    public static final int MAX_DEPTH = 32;

    /** Receives numeric leaves: the field path and the value as a double (a bool 0 or 1). */
    @FunctionalInterface
    public interface NumberSink {
        void number(String path, double value);
    }

    private final String typeName;
    private final MessageType type;
    private final String[] names;
    private final Object[] values;

    /**
     * A message of {@code typeName} with {@code names[i]} = {@code values[i]}; {@code type} is its
     * definition (null for JSON). The arrays are taken, not copied: the decoder hands over its own.
     */
    public RosMessage(String typeName, MessageType type, String[] names, Object[] values) {
        if (names.length != values.length) {
            throw new IllegalArgumentException(names.length + " names for " + values.length + " values");
        }
        this.typeName = typeName;
        this.type = type;
        this.names = names;
        this.values = values;
    }

    /** {@code sensor_msgs/msg/Image}, or for JSON the schema's name (the topic's when there is none). */
    public String typeName() {
        return typeName;
    }

    /** The definition the message was decoded by, or null for JSON. */
    public MessageType type() {
        return type;
    }

    public int fieldCount() {
        return names.length;
    }

    public String name(int i) {
        return names[i];
    }

    public Object value(int i) {
        return values[i];
    }

    /** The value of the field {@code name}, or null when there is none. */
    public Object get(String name) {
        for (int i = 0; i < names.length; i++) {
            if (names[i].equals(name)) {
                return values[i];
            }
        }
        return null;
    }

    /** The value at {@code path} ({@code pose.position.x}, {@code position[3]}), or null when the path names nothing. */
    public Object at(String path) {
        Object at = this;
        int i = 0;
        int n = path.length();
        while (i < n) {
            if (path.charAt(i) == '[') {
                int close = path.indexOf(']', i);
                if (close < 0) {
                    return null;
                }
                int index;
                try {
                    index = Integer.parseInt(path, i + 1, close, 10);
                } catch (NumberFormatException e) {
                    return null;
                }
                at = element(at, index);
                i = close + 1;
            } else {
                if (path.charAt(i) == '.') {
                    i++;
                }
                int end = i;
                while (end < n && path.charAt(end) != '.' && path.charAt(end) != '[') {
                    end++;
                }
                if (!(at instanceof RosMessage m)) {
                    return null;
                }
                at = m.get(path.substring(i, end));
                i = end;
            }
            if (at == null) {
                return null;
            }
        }
        return at;
    }

    /** The number at {@code path} (a bool 0 or 1, a uint64 unsigned), or NaN when it names no number. */
    public double number(String path) {
        int dot = Math.max(path.lastIndexOf('.'), 0);
        Primitive p = primitiveAt(path.substring(0, dot == 0 ? 0 : dot), dot == 0 ? path : path.substring(dot + 1));
        return asNumber(at(path), p);
    }

    private Primitive primitiveAt(String parentPath, String leaf) {
        Object parent = parentPath.isEmpty() ? this : at(parentPath);
        if (!(parent instanceof RosMessage m) || m.type == null) {
            return null;
        }
        int bracket = leaf.indexOf('[');
        String name = bracket < 0 ? leaf : leaf.substring(0, bracket);
        for (Field f : m.type.fields()) {
            if (f.name().equals(name)) {
                return f.primitive();
            }
        }
        return null;
    }

    private static Object element(Object array, int index) {
        if (index < 0 || array == null || !array.getClass().isArray() || index >= java.lang.reflect.Array.getLength(array)) {
            return null;
        }
        return java.lang.reflect.Array.get(array, index);
    }

    private static double asNumber(Object v, Primitive p) {
        if (v instanceof Long l && p == Primitive.UINT64 && l < 0) {
            return (double) (l >>> 1) * 2.0 + (l & 1);
        }
        if (v instanceof Byte b) {
            return p == Primitive.INT8 ? b : b & 0xFF;
        }
        if (v instanceof Short s) {
            return p == Primitive.UINT16 ? s & 0xFFFF : s;
        }
        if (v instanceof Integer i && p == Primitive.UINT32) {
            return i & 0xFFFFFFFFL;
        }
        if (v instanceof Number n) {
            return n.doubleValue();
        }
        if (v instanceof Boolean b) {
            return b ? 1 : 0;
        }
        return Double.NaN;
    }

    /**
     * Hands every numeric leaf to {@code sink} in field order: numbers and bools, in nested
     * messages and arrays (up to {@link #MAX_ENUMERATED_ELEMENTS} elements each, 8-bit arrays
     * not at all); strings are not numbers.
     */
    public void forEachNumber(NumberSink sink) {
        numbers("", sink, 0);
    }

    /**
     * Whether a field name of this message or of one nested in it (as far as {@link #forEachNumber}
     * goes) contains {@code word}, ignoring case: no path it enumerates can contain the word otherwise.
     * Builds no path, so a reader can skip enumerating them for every message.
     */
    public boolean namesContain(String word) {
        return namesContain(word, 0);
    }

    private boolean namesContain(String word, int depth) {
        if (depth >= MAX_DEPTH) {
            return false;
        }
        for (int i = 0; i < names.length; i++) {
            String name = names[i];
            for (int k = 0; k + word.length() <= name.length(); k++) {
                if (name.regionMatches(true, k, word, 0, word.length())) {
                    return true;
                }
            }
            Object v = values[i];
            if (v instanceof RosMessage m && m.namesContain(word, depth + 1)) {
                return true;
            }
            if (v instanceof Object[] a && !(v instanceof String[])) {
                for (int k = 0; k < Math.min(a.length, MAX_ENUMERATED_ELEMENTS); k++) {
                    if (a[k] instanceof RosMessage m && m.namesContain(word, depth + 1)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** The paths {@link #forEachNumber} enumerates, in its order. */
    public List<String> numericPaths() {
        List<String> out = new ArrayList<>();
        forEachNumber((path, v) -> out.add(path));
        return out;
    }

    private void numbers(String prefix, NumberSink sink, int depth) {
        if (depth >= MAX_DEPTH) {
            return;
        }
        for (int i = 0; i < names.length; i++) {
            Primitive p = primitiveOf(i);
            Object v = values[i];
            String path = prefix + names[i];
            if (v instanceof RosMessage m) {
                m.numbers(path + ".", sink, depth + 1);
            } else if (v != null && v.getClass().isArray()) {
                arrayNumbers(path, v, p, sink, depth);
            } else if (v instanceof Number || v instanceof Boolean) {
                sink.number(path, asNumber(v, p));
            }
        }
    }

    private static void arrayNumbers(String path, Object array, Primitive p, NumberSink sink, int depth) {
        if (array instanceof byte[]) {
            return;
        }
        int n = Math.min(java.lang.reflect.Array.getLength(array), MAX_ENUMERATED_ELEMENTS);
        if (array instanceof double[] a) {
            for (int k = 0; k < n; k++) {
                sink.number(path + "[" + k + "]", a[k]);
            }
        } else if (array instanceof float[] a) {
            for (int k = 0; k < n; k++) {
                sink.number(path + "[" + k + "]", a[k]);
            }
        } else if (array instanceof RosMessage[] a) {
            for (int k = 0; k < n; k++) {
                a[k].numbers(path + "[" + k + "].", sink, depth + 1);
            }
        } else if (!(array instanceof String[])) {
            for (int k = 0; k < n; k++) {
                Object e = java.lang.reflect.Array.get(array, k);
                if (e instanceof RosMessage m) {
                    m.numbers(path + "[" + k + "].", sink, depth + 1);
                } else if (e instanceof Number || e instanceof Boolean) {
                    sink.number(path + "[" + k + "]", asNumber(e, p));
                }
            }
        }
    }

    private Primitive primitiveOf(int i) {
        return type == null ? null : type.fields().get(i).primitive();
    }

    /** The message on one line for the network console, at most {@code maxChars} long ({@code …} when cut). */
    public String line(int maxChars) {
        StringBuilder b = new StringBuilder(Math.min(maxChars, 256));
        appendLine(b, maxChars, 0);
        if (b.length() > maxChars) {
            b.setLength(Math.max(0, maxChars - 1));
            b.append('…');
        }
        return b.toString();
    }

    private void appendLine(StringBuilder b, int max, int depth) {
        b.append('{');
        for (int i = 0; i < names.length && b.length() <= max; i++) {
            if (i > 0) {
                b.append(", ");
            }
            b.append(names[i]).append(": ");
            appendValue(b, values[i], primitiveOf(i), max, depth);
        }
        b.append('}');
    }

    private static void appendValue(StringBuilder b, Object v, Primitive p, int max, int depth) {
        if (v instanceof RosMessage m) {
            if (depth + 1 >= MAX_DEPTH) {
                b.append("{…}");
            } else {
                m.appendLine(b, max, depth + 1);
            }
        } else if (v instanceof String s) {
            b.append('"').append(s.length() > max ? s.substring(0, max) : s).append('"');
        } else if (v instanceof byte[] a) {
            b.append('<').append(a.length).append(" bytes>");
        } else if (v != null && v.getClass().isArray()) {
            int n = java.lang.reflect.Array.getLength(v);
            b.append('[');
            for (int k = 0; k < n && b.length() <= max; k++) {
                if (k > 0) {
                    b.append(", ");
                }
                appendValue(b, java.lang.reflect.Array.get(v, k), p, max, depth);
            }
            b.append(']');
        } else if (v instanceof Long l && p == Primitive.UINT64) {
            b.append(Long.toUnsignedString(l));
        } else if (v instanceof Byte x) {
            b.append(p == Primitive.INT8 ? x : x & 0xFF);
        } else if (v instanceof Short x) {
            b.append(p == Primitive.UINT16 ? x & 0xFFFF : x);
        } else if (v instanceof Integer x && p == Primitive.UINT32) {
            b.append(x & 0xFFFFFFFFL);
        } else {
            b.append(v);
        }
    }

    /**
     * The message as indented text ({@code ros2 topic echo}'s shape: one field a line, nested
     * messages indented), at most {@code maxChars} long.
     */
    public String text(int maxChars) {
        StringBuilder b = new StringBuilder(Math.min(maxChars, 1024));
        appendText(b, "", maxChars, 0);
        if (b.length() > maxChars) {
            b.setLength(Math.max(0, maxChars - 1));
            b.append('…');
        }
        return b.toString();
    }

    private void appendText(StringBuilder b, String indent, int max, int depth) {
        for (int i = 0; i < names.length && b.length() <= max; i++) {
            b.append(indent).append(names[i]).append(':');
            Object v = values[i];
            if (v instanceof RosMessage m && depth + 1 < MAX_DEPTH) {
                b.append('\n');
                m.appendText(b, indent + "  ", max, depth + 1);
            } else if (v instanceof RosMessage[] a && a.length > 0 && depth + 1 < MAX_DEPTH) {
                b.append('\n');
                for (RosMessage m : a) {
                    if (b.length() > max) {
                        break;
                    }
                    b.append(indent).append("- \n");
                    m.appendText(b, indent + "    ", max, depth + 1);
                }
            } else {
                b.append(' ');
                appendValue(b, v, primitiveOf(i), max, depth);
                b.append('\n');
            }
        }
    }

    @Override
    public String toString() {
        return typeName + " " + line(400);
    }
}
