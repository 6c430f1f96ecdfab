package touchline.serve;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageKinds;
import touchline.record.SchemaSet;
import touchline.transport.Envelope;

import java.util.Base64;
import java.util.List;

/**
 * What a served channel carries and how it is described: a FUmanoids message of a known kind
 * goes out as its extension's own type (so a viewer plots {@code /robot/3/status.batteryPercent}
 * without knowing the wrapper), anything else as the decoded message itself. The schema is
 * the self-contained FileDescriptorSet the recorder embeds, so a team's types loaded at run
 * time go out too.
 */
final class ChannelSchema {

    private final String schemaName;
    private final String schemaBase64;
    private final FieldDescriptor extension; // null: the whole message is the payload

    private ChannelSchema(Descriptor type, FieldDescriptor extension) {
        this.schemaName = type.getFullName();
        this.schemaBase64 = Base64.getEncoder().encodeToString(
                SchemaSet.descriptorSet(List.of(type.getFile())).toByteArray());
        this.extension = extension;
    }

    /** The schema of {@code e}'s channel; {@code kinds} names the extensions, the team's included. */
    static ChannelSchema of(Envelope e, MessageKinds kinds) {
        Message m = e.message();
        if (m.getDescriptorForType().getFullName().equals(Fumanoid.Message.getDescriptor().getFullName())) {
            FieldDescriptor ext = kinds.byName(e.kind()).orElse(null);
            if (ext != null && ext.getJavaType() == FieldDescriptor.JavaType.MESSAGE) {
                return new ChannelSchema(ext.getMessageType(), ext);
            }
        }
        return new ChannelSchema(m.getDescriptorForType(), null);
    }

    String schemaName() {
        return schemaName;
    }

    String schemaBase64() {
        return schemaBase64;
    }

    /** The protobuf bytes a viewer decodes with this schema. */
    byte[] payload(Envelope e) {
        Message m = e.message();
        if (extension != null) {
            Object value = m.getField(extension);
            if (value instanceof Message inner) {
                return inner.toByteArray();
            }
        }
        return m.toByteArray();
    }
}
