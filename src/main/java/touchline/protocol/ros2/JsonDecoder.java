package touchline.protocol.ros2;

/**
 * Decodes a {@code json} channel's messages (with a {@code jsonschema} schema or none) into
 * the same tree as CDR: one UTF-8 JSON object per message. The schema is not needed to read
 * the values (JSON names them), so it is not enforced.
 */
public final class JsonDecoder implements MessageDecoder {

    private final String typeName;

    /** {@code typeName}: the schema's name, or the topic when the channel has no schema. */
    public JsonDecoder(String typeName) {
        this.typeName = typeName;
    }

    @Override
    public String typeName() {
        return typeName;
    }

    @Override
    public DecodeResult decode(byte[] data, int offset, int length) {
        return new DecodeResult.Undecodable("not implemented yet");
    }
}
