package touchline.protocol;

import com.google.protobuf.ByteString;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import com.google.protobuf.TextFormat;
import com.google.protobuf.UnknownFieldSet;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Renders any message as protobuf text for the network console and the CLI. Known fields look
 * exactly as protobuf's own text format prints them. Extensions no registered type knows are
 * shown field by field (number, wire type, value), nested where the bytes parse as a message,
 * never dropped.
 *
 * <p>The bytes come from outside (robots, NAO replies of any size, recordings), so the work is
 * bounded twice: nesting deeper than {@link #MAX_DEPTH} levels is shown as one marker line with
 * its size, and the text stops after {@link #MAX_CHARS} characters with a marker saying so.
 * Protobuf's own printer has neither bound: 3.5 KB of nested unknown fields overflowed its
 * stack, and one 1 400-byte datagram, indented two spaces per level, printed 470 KB.
 */
public final class MessageText {

    /** Nesting levels shown; deeper blocks become one marker line. */
    public static final int MAX_DEPTH = 32;
    /** Characters of text shown per message; the rest is replaced by a marker. */
    public static final int MAX_CHARS = 16 * 1024;

    private static final int MAX_BYTES_SHOWN = 64;
    // Our own unknown-extension form tries to read bytes as a message this deep only (as before).
    private static final int UNKNOWN_EXTENSION_DEPTH = 8;
    private static final TextFormat.Printer PRINTER = TextFormat.printer();

    public String render(Message message) {
        Text out = new Text();
        fields(out, message, 0);
        for (Map.Entry<Integer, UnknownFieldSet.Field> e : message.getUnknownFields().asMap().entrySet()) {
            unknownExtension(out, "unknown extension " + e.getKey(), e.getValue(), 0);
        }
        return out.finish(message);
    }

    /** One line, for lists: the text form with line breaks folded. */
    public String renderLine(Message message) {
        return foldLines(render(message));
    }

    /**
     * Every run of whitespace that holds a line break becomes one space, and the ends are
     * trimmed: what {@code replaceAll("\\s*\\n\\s*", " ").trim()} did, in one pass (that regex
     * backtracks quadratically over a long run of spaces without a line break).
     */
    static String foldLines(String text) {
        StringBuilder out = new StringBuilder(text.length());
        int i = 0;
        int n = text.length();
        while (i < n) {
            char c = text.charAt(i);
            if (!isRegexSpace(c)) {
                out.append(c);
                i++;
                continue;
            }
            int start = i;
            boolean lineBreak = false;
            while (i < n && isRegexSpace(text.charAt(i))) {
                lineBreak |= text.charAt(i) == '\n';
                i++;
            }
            if (lineBreak) {
                out.append(' ');
            } else {
                out.append(text, start, i);
            }
        }
        return out.toString().trim();
    }

    private static boolean isRegexSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == 0x0B || c == '\f' || c == '\r';
    }

    // ---- known fields, in protobuf's text format ----

    private void fields(Text out, Message message, int depth) {
        for (Map.Entry<FieldDescriptor, Object> e : message.getAllFields().entrySet()) {
            FieldDescriptor field = e.getKey();
            if (field.isRepeated()) {
                for (Object element : elements(field, (List<?>) e.getValue())) {
                    field(out, field, element, depth);
                }
            } else {
                field(out, field, e.getValue(), depth);
            }
        }
    }

    private void field(Text out, FieldDescriptor field, Object value, int depth) {
        if (out.full()) {
            return;
        }
        if (field.getJavaType() != FieldDescriptor.JavaType.MESSAGE) {
            StringBuilder line = new StringBuilder(name(field)).append(": ");
            try {
                PRINTER.printFieldValue(field, value, line);
            } catch (java.io.IOException e) {
                throw new IllegalStateException(e); // a StringBuilder does not throw
            }
            out.line(depth, line);
            return;
        }
        Message nested = (Message) value;
        if (depth + 1 >= MAX_DEPTH) {
            out.line(depth, tooDeep(name(field), nested.getSerializedSize()));
            return;
        }
        out.line(depth, name(field) + " {");
        fields(out, nested, depth + 1);
        unknownFields(out, nested.getUnknownFields(), depth + 1);
        out.line(depth, "}");
    }

    private static String name(FieldDescriptor field) {
        if (field.isExtension()) {
            boolean messageSetItem = field.getContainingType().getOptions().getMessageSetWireFormat()
                    && field.getType() == FieldDescriptor.Type.MESSAGE && field.isOptional()
                    && field.getExtensionScope() == field.getMessageType();
            return "[" + (messageSetItem ? field.getMessageType().getFullName() : field.getFullName()) + "]";
        }
        // proto2 groups keep their type's capitalisation, as protobuf prints them
        return field.getType() == FieldDescriptor.Type.GROUP ? field.getMessageType().getName() : field.getName();
    }

    /** Map entries sorted by key, as protobuf prints them; other repeated fields in order. */
    private static List<?> elements(FieldDescriptor field, List<?> values) {
        if (!field.isMapField()) {
            return values;
        }
        FieldDescriptor key = field.getMessageType().findFieldByNumber(1);
        List<Message> entries = new ArrayList<>();
        for (Object v : values) {
            entries.add((Message) v);
        }
        entries.sort((a, b) -> compareKeys(a.getField(key), b.getField(key)));
        return entries;
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private static int compareKeys(Object a, Object b) {
        return a instanceof Comparable && a.getClass() == b.getClass() ? ((Comparable) a).compareTo(b) : 0;
    }

    /** Unknown fields inside a known message, as protobuf prints them ({@code 5: 7}, {@code 6 { … }}). */
    private void unknownFields(Text out, UnknownFieldSet unknown, int depth) {
        for (Map.Entry<Integer, UnknownFieldSet.Field> e : unknown.asMap().entrySet()) {
            String number = String.valueOf(e.getKey());
            UnknownFieldSet.Field field = e.getValue();
            for (long v : field.getVarintList()) {
                out.line(depth, number + ": " + TextFormat.unsignedToString(v));
            }
            for (int v : field.getFixed32List()) {
                out.line(depth, number + ": " + String.format((Locale) null, "0x%08x", v));
            }
            for (long v : field.getFixed64List()) {
                out.line(depth, number + ": " + String.format((Locale) null, "0x%016x", v));
            }
            for (ByteString bytes : field.getLengthDelimitedList()) {
                if (out.full()) {
                    return;
                }
                UnknownFieldSet nested = parseOrNull(bytes);
                if (nested == null) {
                    out.line(depth, number + ": \"" + TextFormat.escapeBytes(bytes) + "\"");
                } else if (depth + 1 >= MAX_DEPTH) {
                    out.line(depth, tooDeep(number + ":", bytes.size()));
                } else {
                    out.line(depth, number + ": {");
                    unknownFields(out, nested, depth + 1);
                    out.line(depth, "}");
                }
            }
            for (UnknownFieldSet group : field.getGroupList()) {
                if (depth + 1 >= MAX_DEPTH) {
                    out.line(depth, tooDeep(number, group.getSerializedSize()));
                } else {
                    out.line(depth, number + " {");
                    unknownFields(out, group, depth + 1);
                    out.line(depth, "}");
                }
            }
        }
    }

    private static UnknownFieldSet parseOrNull(ByteString bytes) {
        try {
            return UnknownFieldSet.parseFrom(bytes);
        } catch (com.google.protobuf.InvalidProtocolBufferException e) {
            return null;
        }
    }

    // ---- extensions no registered type knows, in our own form ----

    private void unknownExtension(Text out, String label, UnknownFieldSet.Field field, int depth) {
        for (long v : field.getVarintList()) {
            out.line(depth, label + " (varint): " + v);
        }
        for (int v : field.getFixed32List()) {
            out.line(depth, label + " (fixed32): " + Integer.toUnsignedString(v) + " / " + Float.intBitsToFloat(v));
        }
        for (long v : field.getFixed64List()) {
            out.line(depth, label + " (fixed64): " + Long.toUnsignedString(v) + " / " + Double.longBitsToDouble(v));
        }
        for (ByteString bytes : field.getLengthDelimitedList()) {
            if (out.full()) {
                return;
            }
            UnknownFieldSet nested = depth < UNKNOWN_EXTENSION_DEPTH ? tryParse(bytes) : null;
            if (nested != null && !nested.asMap().isEmpty()) {
                out.line(depth, label + " {");
                for (Map.Entry<Integer, UnknownFieldSet.Field> e : nested.asMap().entrySet()) {
                    unknownExtension(out, "field " + e.getKey(), e.getValue(), depth + 1);
                }
                out.line(depth, "}");
            } else {
                out.line(depth, label + " (bytes, " + bytes.size() + "): " + quote(bytes));
            }
        }
        for (UnknownFieldSet group : field.getGroupList()) {
            if (depth + 1 >= MAX_DEPTH) {
                out.line(depth, tooDeep(label + " (group)", group.getSerializedSize()));
                continue;
            }
            out.line(depth, label + " (group) {");
            for (Map.Entry<Integer, UnknownFieldSet.Field> e : group.asMap().entrySet()) {
                unknownExtension(out, "field " + e.getKey(), e.getValue(), depth + 1);
            }
            out.line(depth, "}");
        }
    }

    private static UnknownFieldSet tryParse(ByteString bytes) {
        if (bytes.isEmpty() || isPrintable(bytes)) {
            return null;
        }
        return parseOrNull(bytes);
    }

    private static boolean isPrintable(ByteString bytes) {
        for (int i = 0; i < bytes.size(); i++) {
            int b = bytes.byteAt(i) & 0xFF;
            if (b < 0x20 || b > 0x7E) {
                return false;
            }
        }
        return true;
    }

    private static String quote(ByteString bytes) {
        ByteString shown = bytes.size() > MAX_BYTES_SHOWN ? bytes.substring(0, MAX_BYTES_SHOWN) : bytes;
        return "\"" + TextFormat.escapeBytes(shown) + "\"" + (bytes.size() > MAX_BYTES_SHOWN ? "…" : "");
    }

    private static String tooDeep(String label, int bytes) {
        return label + " { … nested deeper than " + MAX_DEPTH + " levels: " + bytes + " bytes not shown }";
    }

    /** The text being built: two spaces of indent per level, stopping once it holds MAX_CHARS. */
    private static final class Text {
        private final StringBuilder out = new StringBuilder();

        boolean full() {
            return out.length() >= MAX_CHARS;
        }

        void line(int depth, CharSequence text) {
            if (full()) {
                return;
            }
            for (int i = 0; i < depth; i++) {
                out.append("  ");
            }
            out.append(text).append('\n');
        }

        String finish(Message message) {
            if (!full()) {
                return out.toString();
            }
            return out.substring(0, MAX_CHARS) + "\n… the text stops here, at " + MAX_CHARS
                    + " characters; the message is " + message.getSerializedSize() + " bytes (see its raw bytes)\n";
        }
    }
}
