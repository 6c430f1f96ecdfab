package touchline.transport.nao;

import touchline.protocol.nao.MixedValueCodec;

/**
 * How one NAOqi call ended. Every call through {@link NaoLink} completes with exactly one of
 * these and never with an exception, so the UI and CLI switch on the type instead of catching.
 */
public sealed interface CallOutcome {

    /** True for {@link Value} and {@link Done}: the robot ran the call without error. */
    default boolean ok() {
        return this instanceof Value || this instanceof Done;
    }

    /** One line for a status bar or the CLI. */
    String describe();

    /** The method returned a value (decoded, see {@link MixedValueCodec}). */
    record Value(Object value) implements CallOutcome {
        public String describe() {
            return MixedValueCodec.format(value);
        }
    }

    /** A void method finished (the reply had neither value nor error). */
    record Done() implements CallOutcome {
        public String describe() {
            return "done";
        }
    }

    /** The robot answered with an error (unknown method, wrong parameters, module exception) or the reply was unreadable. */
    record Failed(String error) implements CallOutcome {
        public String describe() {
            return "error: " + error;
        }
    }

    /** No reply within the call's timeout (after the allowed retries, for idempotent calls). */
    record TimedOut(long afterMillis) implements CallOutcome {
        public String describe() {
            return "timed out after " + afterMillis + " ms";
        }
    }

    /** The connection was lost (or never came up) before a reply; the call was dropped, never sent late. */
    record Lost(String why) implements CallOutcome {
        public String describe() {
            return "connection lost: " + why;
        }
    }

    /** Not sent: the send gate (match mode) forbids commanding the robot now. */
    record HeldBack(String reason) implements CallOutcome {
        public String describe() {
            return "held back: " + reason;
        }
    }

    /** Not sent: a newer call of the same rate-limited method replaced it within the minimum interval. */
    record Superseded() implements CallOutcome {
        public String describe() {
            return "superseded by a newer call within the minimum interval";
        }
    }
}
