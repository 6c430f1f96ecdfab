package touchline.record;

/**
 * A recording that cannot be opened at all (not MCAP, unreadable). The message is meant for
 * the user as is; problems inside a readable recording are reported as text, not thrown.
 */
public final class RecordingException extends Exception {
    public RecordingException(String message) {
        super(message);
    }
}
