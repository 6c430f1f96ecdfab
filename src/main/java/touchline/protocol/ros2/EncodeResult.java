package touchline.protocol.ros2;

/** The outcome of encoding one message by its definition: the bytes, or why not (naming the field). */
public sealed interface EncodeResult {

    record Encoded(byte[] bytes) implements EncodeResult { }

    /** Values that do not fit the definition, with a one-line reason for the user. */
    record Refused(String reason) implements EncodeResult { }
}
