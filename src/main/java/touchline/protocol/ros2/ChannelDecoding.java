package touchline.protocol.ros2;

/** Whether a channel's messages can be decoded: a decoder, or why not (for the per-channel count the user sees). */
public sealed interface ChannelDecoding {

    record Ready(MessageDecoder decoder) implements ChannelDecoding { }

    /**
     * Not decodable: {@code encoding} is {@code schemaEncoding/messageEncoding} as the channel
     * said it, {@code reason} a sentence ("encoding not supported", "the schema does not parse:
     * line 3: ...").
     */
    record Unsupported(String encoding, String reason) implements ChannelDecoding { }
}
