package touchline.model;

/** A rule profile that cannot be read; the message names the file and what is wrong. */
public final class RuleProfileException extends Exception {

    public RuleProfileException(String message) {
        super(message);
    }
}
