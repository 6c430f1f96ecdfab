package touchline.protocol.nao;

/** A value that cannot be converted between Java and the MixedValue wire form; the message says why. */
public final class MixedValueException extends RuntimeException {
    public MixedValueException(String message) {
        super(message);
    }
}
