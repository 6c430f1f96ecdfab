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
final class ChannelSchema implements ChannelPayloads {

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

    /**
     * {@code recorded} (the recording's channel metadata of the first envelope) and what the
     * payload is: {@value #SERVED_EXTENSION} (the extension's own message, to be put back into a
     * {@code fumanoid.Message} of the channel's robot) or {@value #SERVED_MESSAGE} (the whole
     * decoded message). Another Touchline rebuilds the envelopes from this.
     */
    java.util.Map<String, String> metadata(java.util.Map<String, String> recorded) {
        java.util.Map<String, String> m = new java.util.LinkedHashMap<>(recorded);
        m.put(SERVED_KEY, extension != null ? SERVED_EXTENSION : SERVED_MESSAGE);
        return m;
    }

    static final String SERVED_KEY = "touchline.served";
    static final String SERVED_EXTENSION = "extension";
    static final String SERVED_MESSAGE = "message";

    /** The protobuf bytes a viewer decodes with this schema. */
    @Override
    public byte[] payload(Envelope e) {
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
