package touchline.protocol;

import com.google.protobuf.ByteString;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;

/**
 * The debug data a message carries: its extension's value and the {@code option} string
 * every data message has by convention (teams' own types too). Our own data types are read
 * through their generated getters; only teams' types go through protobuf reflection, which
 * cost the model more per datagram than decoding it. Pure.
 */
public final class DebugData {

    private final MessageKinds kinds;

    public DebugData(MessageKinds kinds) {
        this.kinds = kinds;
    }

    private static final java.util.Set<String> OWN_KINDS = Fumanoid.getDescriptor().getExtensions().stream()
            .map(FieldDescriptor::getName).collect(java.util.stream.Collectors.toUnmodifiableSet());

    /** True for the kinds {@code fumanoid.proto} itself declares (data or not); false for teams' own. */
    public static boolean isOwnKind(String kind) {
        return OWN_KINDS.contains(kind);
    }

    /** The extension value of {@code kind} in {@code m}, or null when there is none or it is no message. */
    public Message dataOf(String kind, Fumanoid.Message m) {
        Message own = ownDataOf(kind, m);
        if (own != null || isOwnKind(kind)) {
            return own;
        }
        FieldDescriptor ext = kinds.byName(kind).orElse(null);
        if (ext == null || ext.getJavaType() != FieldDescriptor.JavaType.MESSAGE || ext.isRepeated() || !m.hasField(ext)) {
            return null;
        }
        return (Message) m.getField(ext);
    }

    /** The debug data of one of our own data kinds, through the generated getters; null for any other kind. */
    public static Message ownDataOf(String kind, Fumanoid.Message m) {
        switch (kind) {
            case "debugText": return m.hasExtension(Fumanoid.debugText) ? m.getExtension(Fumanoid.debugText) : null;
            case "debugPlot": return m.hasExtension(Fumanoid.debugPlot) ? m.getExtension(Fumanoid.debugPlot) : null;
            case "debugTable": return m.hasExtension(Fumanoid.debugTable) ? m.getExtension(Fumanoid.debugTable) : null;
            case "regionGrowing":
                return m.hasExtension(Fumanoid.regionGrowing) ? m.getExtension(Fumanoid.regionGrowing) : null;
            case "grid": return m.hasExtension(Fumanoid.grid) ? m.getExtension(Fumanoid.grid) : null;
            case "relativePositions":
                return m.hasExtension(Fumanoid.relativePositions) ? m.getExtension(Fumanoid.relativePositions) : null;
            case "debugImage": return m.hasExtension(Fumanoid.debugImage) ? m.getExtension(Fumanoid.debugImage) : null;
            case "fieldObjects":
                return m.hasExtension(Fumanoid.fieldObjects) ? m.getExtension(Fumanoid.fieldObjects) : null;
            default: return null;
        }
    }

    /** The {@code option} string of a data message, or null when it has none. */
    public static String optionOf(Message data) {
        ByteString own = ownOptionBytesOf(data);
        if (own != null) {
            return own.toStringUtf8(); // what the generated getter returns
        }
        FieldDescriptor name = data.getDescriptorForType().findFieldByName("option");
        if (name != null && name.getType() == FieldDescriptor.Type.STRING && !name.isRepeated() && data.hasField(name)) {
            return (String) data.getField(name);
        }
        return null;
    }

    /**
     * The {@code option} of one of our own data types as the bytes it came in (nothing decoded),
     * or null when {@code data} is another type or has no option: a caller that decodes names
     * once ({@code touchline.model.Utf8Names}) then falls back to {@link #optionOf(Message)}.
     */
    public static ByteString ownOptionBytesOf(Message data) {
        if (data instanceof Fumanoid.DebugPlot d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.DebugText d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.RegionGrowing d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.DebugTable d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.Grid d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.RelativePositions d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.FieldObjects d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        } else if (data instanceof Fumanoid.DebugImage d) {
            return d.hasOption() ? d.getOptionBytes() : null;
        }
        return null;
    }

    /** The option name of the data {@code m} carries as {@code kind}, or null. */
    public String optionOf(String kind, Fumanoid.Message m) {
        Message data = dataOf(kind, m);
        return data == null ? null : optionOf(data);
    }
}
