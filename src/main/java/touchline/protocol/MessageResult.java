package touchline.protocol;

import touchline.proto.Fumanoid;

/** The outcome of decoding a FUmanoids protobuf payload. */
public sealed interface MessageResult {

    /**
     * A decoded {@code Message}. {@code extension} is the number of the extension it carries
     * (0 when it carries none); {@code kind} is that extension's name or {@code ext#N} when
     * no registered type knows it (its fields are then kept as unknown fields, not dropped).
     */
    record Decoded(Fumanoid.Message message, int extension, String kind) implements MessageResult { }

    /** Bytes that are not a valid {@code Message}, with a one-line reason. */
    record Malformed(String reason) implements MessageResult { }
}
