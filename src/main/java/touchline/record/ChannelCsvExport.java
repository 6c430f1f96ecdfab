package touchline.record;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.EnumValueDescriptor;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import com.google.protobuf.DynamicMessage;
import com.google.protobuf.ExtensionRegistry;
import com.google.protobuf.InvalidProtocolBufferException;
import com.google.protobuf.Message;
import touchline.protocol.ros2.ChannelDecoders;
import touchline.protocol.ros2.ChannelDecoding;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.MessageDecoder;
import touchline.protocol.ros2.RosMessage;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Any protobuf channel of an MCAP file as CSV: one row per message, the log time first
 * ({@code time}: seconds since the recording started; {@code log_time_ns}: the message's own
 * log time), then one column per numeric, boolean, enum or text leaf field path the channel's
 * messages carry, flattened with dots ({@code status.robotPosition.x}) and repeated fields
 * indexed ({@code samples[0].value}); an extension is named by its field name. Columns are in
 * order of first appearance; a message without a field leaves its cell empty. Bytes fields
 * (images) are left out. Decoded with the channel's own schema, so it works on any file,
 * Touchline's own and exports alike. A ROS 2 channel (ros2msg/ros2idl with CDR) or a JSON
 * channel exports its numeric leaves the same way ({@code pose.position.x}, {@code position[3]};
 * bools as 0/1, 8-bit arrays left out). Reads the file twice (columns, then rows).
 */
public final class ChannelCsvExport {

    /** The channel cannot be exported (no such topic, no protobuf schema); the message says why. */
    public static final class NotExportable extends Exception {
        NotExportable(String message) {
            super(message);
        }
    }

    /** What was written: rows, and messages that did not decode (left out). */
    public record Result(long rows, long undecodable) { }

    private final Recording recording;

    public ChannelCsvExport(Recording recording) {
        this.recording = recording;
    }

    /** Writes the CSV of {@code topic}. */
    public Result write(String topic, Writer out) throws IOException, NotExportable {
        McapReader mcap = recording.mcap();
        Map<Integer, Descriptor> types = new HashMap<>();
        Map<Integer, MessageDecoder> decoders = new HashMap<>();
        List<String> notExportable = new ArrayList<>();
        SchemaSet schemas = new SchemaSet();
        for (McapReader.ChannelInfo c : mcap.channels().values()) {
            if (!c.topic().equals(topic)) {
                continue;
            }
            McapReader.Schema s = mcap.schemas().get(c.schemaId());
            if (s != null && s.encoding().equals("protobuf") && c.messageEncoding().equals("protobuf")) {
                types.put(c.id(), type(schemas, s));
                continue;
            }
            ChannelDecoding d = new ChannelDecoders().decoding(topic, c.messageEncoding(), s == null ? "" : s.name(),
                    s == null ? "" : s.encoding(), s == null ? new byte[0] : s.data());
            if (d instanceof ChannelDecoding.Ready r) {
                decoders.put(c.id(), r.decoder());
            } else {
                ChannelDecoding.Unsupported u = (ChannelDecoding.Unsupported) d;
                notExportable.add(u.encoding() + " (" + u.reason() + ")");
            }
        }
        if (types.isEmpty() && decoders.isEmpty()) {
            if (!notExportable.isEmpty()) {
                throw new NotExportable("channel " + topic + " carries " + notExportable.get(0)
                        + "; protobuf, ROS 2 (CDR) and JSON channels export as CSV");
            }
            throw new NotExportable("the recording has no channel " + topic + " (channels: "
                    + String.join(", ", mcap.channels().values().stream().map(McapReader.ChannelInfo::topic)
                    .distinct().sorted().toList()) + ")");
        }
        ExtensionRegistry extensions = extensions(schemas);
        Map<String, Integer> columns = new LinkedHashMap<>();
        long undecodable = 0;
        McapReader.Cursor c = mcap.cursor(0);
        for (McapReader.McapMessage m = c.next(); m != null; m = c.next()) {
            Map<String, String> cells = cells(types, decoders, extensions, m);
            if (cells != null) {
                cells.keySet().forEach(k -> columns.putIfAbsent(k, columns.size()));
            } else if (types.containsKey(m.channelId()) || decoders.containsKey(m.channelId())) {
                undecodable++;
            }
        }
        out.write("time,log_time_ns");
        for (String name : columns.keySet()) {
            out.write(',');
            out.write(DebugCsvExport.cell(name));
        }
        out.write('\n');
        long rows = 0;
        String[] row = new String[columns.size()];
        c = mcap.cursor(0);
        for (McapReader.McapMessage m = c.next(); m != null; m = c.next()) {
            Map<String, String> cells = cells(types, decoders, extensions, m);
            if (cells == null) {
                continue;
            }
            java.util.Arrays.fill(row, "");
            cells.forEach((k, v) -> row[columns.get(k)] = DebugCsvExport.cell(v));
            long d = m.logTime() - mcap.startTime();
            out.write(String.format(Locale.ROOT, "%s%d.%09d,%d", d < 0 ? "-" : "", Math.abs(d) / 1_000_000_000L,
                    Math.abs(d) % 1_000_000_000L, m.logTime()));
            for (String v : row) {
                out.write(',');
                out.write(v);
            }
            out.write('\n');
            rows++;
        }
        return new Result(rows, undecodable);
    }

    private static Descriptor type(SchemaSet schemas, McapReader.Schema s) throws NotExportable {
        try {
            List<FileDescriptor> added = schemas.add(FileDescriptorSet.parseFrom(s.data()));
            for (FileDescriptor f : schemas.files()) {
                Descriptor d = f.getPackage().isEmpty() || s.name().startsWith(f.getPackage() + ".")
                        ? f.findMessageTypeByName(f.getPackage().isEmpty() ? s.name()
                        : s.name().substring(f.getPackage().length() + 1)) : null;
                if (d != null) {
                    return d;
                }
            }
            throw new NotExportable("schema " + s.name() + " is not in its own descriptor set (" + added.size()
                    + " files added)");
        } catch (InvalidProtocolBufferException | RecordingException e) {
            throw new NotExportable("schema " + s.name() + " does not parse: " + e.getMessage());
        }
    }

    private static ExtensionRegistry extensions(SchemaSet schemas) {
        ExtensionRegistry r = ExtensionRegistry.newInstance();
        for (FileDescriptor f : schemas.files()) {
            for (FieldDescriptor x : f.getExtensions()) {
                if (x.getJavaType() == FieldDescriptor.JavaType.MESSAGE) {
                    r.add(x, DynamicMessage.getDefaultInstance(x.getMessageType()));
                } else {
                    r.add(x);
                }
            }
        }
        return r;
    }

    /**
     * The cells of {@code m}: a protobuf message's leaves, a ROS 2 or JSON message's numeric
     * leaves ({@link RosMessage#forEachNumber}); null when its channel is another topic's or the
     * message does not decode.
     */
    private static Map<String, String> cells(Map<Integer, Descriptor> types, Map<Integer, MessageDecoder> decoders,
                                             ExtensionRegistry extensions, McapReader.McapMessage m) {
        MessageDecoder decoder = decoders.get(m.channelId());
        if (decoder != null) {
            if (!(decoder.decode(m.data()) instanceof DecodeResult.Decoded d)) {
                return null;
            }
            Map<String, String> cells = new LinkedHashMap<>();
            d.message().forEachNumber((path, v) -> cells.put(path,
                    v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v)));
            return cells;
        }
        Message msg = decode(types, extensions, m);
        if (msg == null) {
            return null;
        }
        Map<String, String> cells = new LinkedHashMap<>();
        flatten("", msg, cells);
        return cells;
    }

    private static Message decode(Map<Integer, Descriptor> types, ExtensionRegistry extensions,
                                  McapReader.McapMessage m) {
        Descriptor type = types.get(m.channelId());
        if (type == null) {
            return null;
        }
        try {
            return DynamicMessage.parseFrom(type, m.data(), extensions);
        } catch (InvalidProtocolBufferException e) {
            return null;
        }
    }

    /** Adds every leaf of {@code m} under {@code prefix} to {@code cells}. */
    static void flatten(String prefix, Message m, Map<String, String> cells) {
        List<FieldDescriptor> fields = new ArrayList<>(m.getDescriptorForType().getFields());
        for (FieldDescriptor f : m.getAllFields().keySet()) {
            if (f.isExtension()) {
                fields.add(f);
            }
        }
        for (FieldDescriptor f : fields) {
            String name = prefix + f.getName();
            if (f.isRepeated()) {
                int n = m.getRepeatedFieldCount(f);
                for (int i = 0; i < n; i++) {
                    leaf(name + "[" + i + "]", f, m.getRepeatedField(f, i), cells);
                }
            } else if (f.getJavaType() == FieldDescriptor.JavaType.MESSAGE) {
                if (m.hasField(f)) {
                    flatten(name + ".", (Message) m.getField(f), cells);
                }
            } else if (!f.hasPresence() || m.hasField(f)) {
                leaf(name, f, m.getField(f), cells);
            }
        }
    }

    private static void leaf(String name, FieldDescriptor f, Object value, Map<String, String> cells) {
        switch (f.getJavaType()) {
            case MESSAGE -> flatten(name + ".", (Message) value, cells);
            case BYTE_STRING -> { } // images and blobs are no cell
            case ENUM -> cells.put(name, ((EnumValueDescriptor) value).getName());
            case INT -> cells.put(name, f.getType() == FieldDescriptor.Type.UINT32 || f.getType() == FieldDescriptor.Type.FIXED32
                    ? Integer.toUnsignedString((Integer) value) : value.toString());
            case LONG -> cells.put(name, f.getType() == FieldDescriptor.Type.UINT64 || f.getType() == FieldDescriptor.Type.FIXED64
                    ? Long.toUnsignedString((Long) value) : value.toString());
            default -> cells.put(name, value.toString());
        }
    }
}
