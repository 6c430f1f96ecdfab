package touchline.protocol.ros2;

/** The outcome of decoding one message by its channel's definition. */
public sealed interface DecodeResult {

    record Decoded(RosMessage message) implements DecodeResult { }

    /** Bytes that do not fit the definition, with a one-line reason (where in the message it failed). */
    record Undecodable(String reason) implements DecodeResult { }
}
