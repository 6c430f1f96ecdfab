package touchline.security;

/** A key file that is missing, unreadable or wrong, with what to do about it in the message. */
public final class KeyException extends Exception {
    public KeyException(String message) {
        super(message);
    }
}
