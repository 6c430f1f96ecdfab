package touchline.protocol.gamecontroller;

import java.util.Objects;

/**
 * The outcome of decoding one datagram: either a value, or the reason it was rejected.
 * Decoders return this instead of throwing, so bad input from the field is a counted,
 * visible value and never an exception in a network thread.
 *
 * @param value   the decoded value, null when rejected
 * @param failure why it was rejected, null when decoded
 * @param detail  human-readable detail of the rejection ("" when decoded)
 */
public record Decoded<T>(T value, DecodeFailure failure, String detail) {

    public static <T> Decoded<T> ok(T value) {
        return new Decoded<>(Objects.requireNonNull(value), null, "");
    }

    public static <T> Decoded<T> rejected(DecodeFailure failure, String detail) {
        return new Decoded<>(null, Objects.requireNonNull(failure), detail);
    }

    public boolean isOk() {
        return failure == null;
    }

    /** Re-types a rejection (only valid when not ok). */
    public <U> Decoded<U> asRejected() {
        if (isOk()) {
            throw new IllegalStateException("not a rejection");
        }
        return new Decoded<>(null, failure, detail);
    }

    @Override
    public String toString() {
        return isOk() ? "ok " + value : failure + ": " + detail;
    }
}
