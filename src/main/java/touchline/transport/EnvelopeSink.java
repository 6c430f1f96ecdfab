package touchline.transport;

/**
 * Where envelopes go. Called on a network (or replay) thread: implementations must be
 * thread-safe and must not block, and never touch JavaFX nodes.
 */
@FunctionalInterface
public interface EnvelopeSink {
    void accept(Envelope envelope);
}
