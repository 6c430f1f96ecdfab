package touchline.protocol;

/** The outcome of taking the header off a datagram: a payload, or the reason it has none. */
public sealed interface FrameResult {

    /** A well-formed frame; {@code payload} is the protobuf bytes behind the header. */
    record Frame(Framing framing, byte[] payload) implements FrameResult { }

    /** A datagram that is not a valid frame, with a one-line reason for the user. */
    record Malformed(String reason) implements FrameResult { }
}
