package touchline.fuzz;

import java.util.List;

/**
 * One decoder of outside input under fuzzing. {@link #accept} feeds it one input and returns
 * normally when the decoder accepts the bytes or rejects them the way it declares (its error
 * value or exception); anything else it throws is a finding: another exception, a broken
 * property (an {@link AssertionError}), a {@link StackOverflowError} or an out-of-memory.
 */
public interface FuzzTarget {

    /** The name on the command line and of the corpus directory, e.g. {@code framing}. */
    String name();

    /** Feeds one input; throws only for a finding. */
    void accept(byte[] input);

    /** Well-formed inputs to start from: golden files and sample messages. */
    List<byte[]> seeds();

    /**
     * Sets up what the inputs need before the fuzzer's clock runs (a server, its first
     * connection, the code it loads), so the first input is not a timeout; called once.
     */
    default void prepare() {
    }

    /** Stops what the target started for its inputs (a server); a target of pure decoders has nothing. */
    default void close() {
    }

    /** Throws a finding unless {@code property} holds. */
    static void check(boolean property, String what) {
        if (!property) {
            throw new AssertionError(what);
        }
    }
}
