package touchline.protocol;

import com.google.protobuf.ByteString;
import com.google.protobuf.Message;
import com.google.protobuf.TextFormat;
import com.google.protobuf.UnknownFieldSet;

import java.util.Map;

/**
 * Renders any message as protobuf text for the network console and the CLI. Extensions no
 * registered type knows are shown field by field (number, wire type, value), nested where the
 * bytes parse as a message, never dropped.
 */
public final class MessageText {

    private static final int MAX_BYTES_SHOWN = 64;

    public String render(Message message) {
        StringBuilder out = new StringBuilder();
        Message known = message.toBuilder().setUnknownFields(UnknownFieldSet.getDefaultInstance()).build();
        out.append(TextFormat.printer().printToString(known));
        UnknownFieldSet unknown = message.getUnknownFields();
        if (!unknown.asMap().isEmpty()) {
            for (Map.Entry<Integer, UnknownFieldSet.Field> e : unknown.asMap().entrySet()) {
                appendUnknown(out, "", "unknown extension " + e.getKey(), e.getValue(), 0);
            }
        }
        return out.toString();
    }

    /** One line, for lists: the text form with line breaks folded. */
    public String renderLine(Message message) {
        return render(message).replaceAll("\\s*\\n\\s*", " ").trim();
    }

    private void appendUnknown(StringBuilder out, String indent, String label, UnknownFieldSet.Field field, int depth) {
        for (long v : field.getVarintList()) {
            out.append(indent).append(label).append(" (varint): ").append(v).append('\n');
        }
        for (int v : field.getFixed32List()) {
            out.append(indent).append(label).append(" (fixed32): ").append(Integer.toUnsignedString(v))
                    .append(" / ").append(Float.intBitsToFloat(v)).append('\n');
        }
        for (long v : field.getFixed64List()) {
            out.append(indent).append(label).append(" (fixed64): ").append(Long.toUnsignedString(v))
                    .append(" / ").append(Double.longBitsToDouble(v)).append('\n');
        }
        for (ByteString bytes : field.getLengthDelimitedList()) {
            UnknownFieldSet nested = depth < 8 ? tryParse(bytes) : null;
            if (nested != null && !nested.asMap().isEmpty()) {
                out.append(indent).append(label).append(" {\n");
                for (Map.Entry<Integer, UnknownFieldSet.Field> e : nested.asMap().entrySet()) {
                    appendUnknown(out, indent + "  ", "field " + e.getKey(), e.getValue(), depth + 1);
                }
                out.append(indent).append("}\n");
            } else {
                out.append(indent).append(label).append(" (bytes, ").append(bytes.size()).append("): ")
                        .append(quote(bytes)).append('\n');
            }
        }
        for (UnknownFieldSet group : field.getGroupList()) {
            out.append(indent).append(label).append(" (group) {\n");
            for (Map.Entry<Integer, UnknownFieldSet.Field> e : group.asMap().entrySet()) {
                appendUnknown(out, indent + "  ", "field " + e.getKey(), e.getValue(), depth + 1);
            }
            out.append(indent).append("}\n");
        }
    }

    private static UnknownFieldSet tryParse(ByteString bytes) {
        if (bytes.isEmpty() || isPrintable(bytes)) {
            return null;
        }
        try {
            return UnknownFieldSet.parseFrom(bytes);
        } catch (Exception e) {
            return null;
        }
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
}
