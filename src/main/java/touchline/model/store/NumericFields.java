package touchline.model.store;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;

import java.util.ArrayList;
import java.util.List;

/**
 * The numeric leaves of a message type as dotted field paths ({@code pose.x}, {@code battery}),
 * read from its protobuf descriptor, so the teams' own types loaded at run time offer theirs
 * like ours; and the value at such a path in one message. Singular fields only (a repeated
 * field has no one value to plot); nested messages up to {@link #MAX_DEPTH} deep, which also
 * stops recursive types. Pure.
 */
public final class NumericFields {

    static final int MAX_DEPTH = 5;

    private NumericFields() {
    }

    /** Every plottable path of {@code type}, in declaration order. */
    public static List<String> paths(Descriptor type) {
        List<String> out = new ArrayList<>();
        collect(type, "", 0, out);
        return out;
    }

    private static void collect(Descriptor type, String prefix, int depth, List<String> out) {
        for (FieldDescriptor f : type.getFields()) {
            if (f.isRepeated()) {
                continue;
            }
            String path = prefix + f.getName();
            if (numeric(f)) {
                out.add(path);
            } else if (f.getJavaType() == FieldDescriptor.JavaType.MESSAGE && depth + 1 < MAX_DEPTH) {
                collect(f.getMessageType(), path + ".", depth + 1, out);
            }
        }
    }

    static boolean numeric(FieldDescriptor f) {
        return switch (f.getJavaType()) {
            case INT, LONG, FLOAT, DOUBLE, BOOLEAN, ENUM -> true;
            default -> false;
        };
    }

    /**
     * The value at {@code path} in {@code m} as a double (a bool is 0 or 1, an enum its
     * number), or NaN when the path does not name a numeric field of this message or a message
     * on the way is absent (an absent number is its default, as protobuf reads it).
     */
    public static double value(Message m, String path) {
        Message at = m;
        int from = 0;
        while (true) {
            int dot = path.indexOf('.', from);
            String name = dot < 0 ? path.substring(from) : path.substring(from, dot);
            FieldDescriptor f = at.getDescriptorForType().findFieldByName(name);
            if (f == null || f.isRepeated()) {
                return Double.NaN;
            }
            if (dot < 0) {
                return numeric(f) ? asDouble(at.getField(f)) : Double.NaN;
            }
            if (f.getJavaType() != FieldDescriptor.JavaType.MESSAGE || !at.hasField(f)) {
                return Double.NaN;
            }
            at = (Message) at.getField(f);
            from = dot + 1;
        }
    }

    private static double asDouble(Object v) {
        if (v instanceof Number n) {
            return n.doubleValue();
        }
        if (v instanceof Boolean b) {
            return b ? 1 : 0;
        }
        if (v instanceof com.google.protobuf.Descriptors.EnumValueDescriptor e) {
            return e.getNumber();
        }
        return Double.NaN;
    }
}
