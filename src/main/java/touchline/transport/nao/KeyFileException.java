package touchline.transport.nao;

/**
 * A key file that cannot be used: missing, unreadable, corrupted, or holding a key of the wrong
 * length. The message names the file, says what is wrong and how to recover (docs/security.md).
 */
public final class KeyFileException extends Exception {

    public KeyFileException(String message) {
        super(message);
    }
}
