package touchline.protocol.ros2;

import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Encodes a message a person wrote as JSON field values into CDR by a {@link MessageDefinition}
 * — the inverse of {@link CdrDecoder}, for a client publish to a ROS 2 robot: little-endian
 * (encapsulation {@code 00 01 00 00}), each primitive aligned to its size counted from after
 * the header, strings with their length and NUL, sequences with a uint32 length, fixed arrays
 * without one, a type without fields as one zero byte. A field left out is zero, false, "" or
 * empty (not the definition's default value); a field the type does not have, a value of the
 * wrong kind or out of its type's range, a fixed array of the wrong length or a sequence over
 * its bound is refused with the field's path. Pure and thread-safe.
 */
public final class CdrEncoder {

    private final MessageDefinition definition;

    public CdrEncoder(MessageDefinition definition) {
        this.definition = definition;
    }

    public String typeName() {
        return definition.rootName();
    }

    /** {@code json}: one JSON object, the root type's field values. */
    public EncodeResult encode(String json) {
        JSONObject value;
        try {
            value = new JSONObject(json);
        } catch (JSONException e) {
            return new EncodeResult.Refused("not a JSON object: " + e.getMessage());
        }
        return encode(value);
    }

    public EncodeResult encode(JSONObject value) {
        Writer w = new Writer();
        try {
            w.message(definition.root(), value, "", 0);
        } catch (Mismatch e) {
            return new EncodeResult.Refused(e.getMessage());
        }
        return new EncodeResult.Encoded(w.bytes());
    }

    /** Raised inside the encoder when a value does not fit; becomes {@link EncodeResult.Refused}. */
    private static final class Mismatch extends Exception {
        Mismatch(String message) {
            super(message, null, false, false);
        }
    }

    /** A growing array of bytes (protocol code touches no streams). */
    private static final class Bytes {
        private byte[] data = new byte[64];
        private int size;

        void write(int b) {
            room(1);
            data[size++] = (byte) b;
        }

        void write(byte[] b, int offset, int length) {
            room(length);
            System.arraycopy(b, offset, data, size, length);
            size += length;
        }

        private void room(int more) {
            if (size + more > data.length) {
                data = Arrays.copyOf(data, Math.max(data.length * 2, size + more));
            }
        }

        void writeBytes(byte[] b) {
            write(b, 0, b.length);
        }

        int size() {
            return size;
        }

        byte[] toByteArray() {
            return Arrays.copyOf(data, size);
        }
    }

    /** The bytes of one message as they are written, aligned from after the header. */
    private final class Writer {
        private final Bytes out = new Bytes();
        private final ByteBuffer scratch = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN);

        Writer() {
            out.writeBytes(new byte[]{0, 1, 0, 0});
        }

        byte[] bytes() {
            return out.toByteArray();
        }

        void message(MessageType type, JSONObject value, String path, int depth) throws Mismatch {
            if (depth > DefinitionParser.MAX_NESTING) {
                throw new Mismatch(type.name() + " nests deeper than " + DefinitionParser.MAX_NESTING + " levels");
            }
            for (String key : value.keySet()) {
                if (type.fields().stream().noneMatch(f -> f.name().equals(key))) {
                    throw new Mismatch(type.name() + " has no field " + path + key);
                }
            }
            if (type.fields().isEmpty()) {
                out.write(0);
                return;
            }
            for (Field f : type.fields()) {
                Object v = value.opt(f.name());
                field(f, v == JSONObject.NULL ? null : v, path + f.name(), depth);
            }
        }

        private void field(Field f, Object v, String path, int depth) throws Mismatch {
            if (f.shape() == Field.Shape.SINGLE) {
                element(f, v, path, depth);
                return;
            }
            if (v != null && !(v instanceof JSONArray)) {
                throw new Mismatch(path + " is " + f.typeText() + ": a list [..] is needed, not " + v);
            }
            JSONArray list = v == null ? new JSONArray() : (JSONArray) v;
            int n = list.length();
            if (f.shape() == Field.Shape.FIXED_ARRAY) {
                if (v != null && n != f.bound()) {
                    throw new Mismatch(path + " is " + f.typeText() + ": exactly " + f.bound() + " values, not " + n);
                }
                n = f.bound();
            } else {
                if (f.shape() == Field.Shape.BOUNDED_SEQUENCE && n > f.bound()) {
                    throw new Mismatch(path + " is " + f.typeText() + ": at most " + f.bound() + " values, not " + n);
                }
                number(4, n);
            }
            for (int k = 0; k < n; k++) {
                Object e = k < list.length() ? list.opt(k) : null;
                element(f, e == JSONObject.NULL ? null : e, path + "[" + k + "]", depth);
            }
        }

        private void element(Field f, Object v, String path, int depth) throws Mismatch {
            if (f.isMessage()) {
                if (v != null && !(v instanceof JSONObject)) {
                    throw new Mismatch(path + " is " + f.typeName() + ": an object {..} is needed, not " + v);
                }
                message(definition.type(f.typeName()), v == null ? new JSONObject() : (JSONObject) v, path + ".",
                        depth + 1);
                return;
            }
            Primitive p = f.primitive();
            switch (p) {
                case STRING -> {
                    byte[] text = text(v, p, f, path).getBytes(StandardCharsets.UTF_8);
                    number(4, text.length + 1);
                    out.writeBytes(text);
                    out.write(0);
                }
                case WSTRING -> {
                    int[] chars = text(v, p, f, path).codePoints().toArray();
                    number(4, chars.length);
                    for (int c : chars) {
                        number(4, c);
                    }
                }
                case BOOL -> {
                    if (v != null && !(v instanceof Boolean)) {
                        throw new Mismatch(path + " is bool: true or false, not " + v);
                    }
                    out.write(Boolean.TRUE.equals(v) ? 1 : 0);
                }
                case FLOAT32 -> {
                    align(4);
                    scratch.clear();
                    out.write(scratch.putFloat(0, (float) real(v, p, path)).array(), 0, 4);
                }
                case FLOAT64 -> {
                    align(8);
                    scratch.clear();
                    out.write(scratch.putDouble(0, real(v, p, path)).array(), 0, 8);
                }
                default -> number(p.size(), integer(v, p, path));
            }
        }

        private String text(Object v, Primitive p, Field f, String path) throws Mismatch {
            if (v != null && !(v instanceof String)) {
                throw new Mismatch(path + " is " + p.word() + ": a \"text\" is needed, not " + v);
            }
            String s = v == null ? "" : (String) v;
            if (f.stringBound() > 0 && s.length() > f.stringBound()) {
                throw new Mismatch(path + " is " + p.word() + "<=" + f.stringBound() + ": " + s.length()
                        + " characters are too many");
            }
            return s;
        }

        private double real(Object v, Primitive p, String path) throws Mismatch {
            if (v != null && !(v instanceof Number)) {
                throw new Mismatch(path + " is " + p.word() + ": a number is needed, not " + v);
            }
            return v == null ? 0 : ((Number) v).doubleValue();
        }

        /** A whole number in {@code p}'s range, as the bits to write. */
        private long integer(Object v, Primitive p, String path) throws Mismatch {
            if (v == null) {
                return 0;
            }
            BigInteger n;
            try {
                n = v instanceof Number num ? new BigDecimal(num.toString()).toBigIntegerExact() : null;
            } catch (ArithmeticException | NumberFormatException e) {
                n = null;
            }
            if (n == null) {
                throw new Mismatch(path + " is " + p.word() + ": a whole number is needed, not " + v);
            }
            int bits = p.size() * 8;
            boolean signed = p.name().startsWith("INT");
            BigInteger min = signed ? BigInteger.ONE.shiftLeft(bits - 1).negate() : BigInteger.ZERO;
            BigInteger max = signed ? BigInteger.ONE.shiftLeft(bits - 1).subtract(BigInteger.ONE)
                    : BigInteger.ONE.shiftLeft(bits).subtract(BigInteger.ONE);
            if (n.compareTo(min) < 0 || n.compareTo(max) > 0) {
                throw new Mismatch(path + " is " + p.word() + ": " + n + " is outside " + min + " to " + max);
            }
            return n.longValue();
        }

        /** {@code size} bytes of {@code bits}, little-endian, aligned to {@code size}. */
        private void number(int size, long bits) {
            align(size);
            for (int i = 0; i < size; i++) {
                out.write((int) (bits >>> (8 * i)));
            }
        }

        private void align(int size) {
            int rel = out.size() - 4;
            int mis = rel & (size - 1);
            for (int i = mis == 0 ? 0 : size - mis; i > 0; i--) {
                out.write(0);
            }
        }
    }
}
