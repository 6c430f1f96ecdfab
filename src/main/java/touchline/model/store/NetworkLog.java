package touchline.model.store;

import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.List;
import java.util.function.Predicate;

/**
 * The network console's memory: the last envelopes in and out, in one capped ring. Envelopes
 * are immutable, so the views can render text and hex from them later on the UI thread.
 */
public final class NetworkLog implements EnvelopeSink {

    public static final int DEFAULT_CAPACITY = 10_000;
    private final SequencedRing<Envelope> envelopes;

    public NetworkLog(int capacity) {
        this.envelopes = new SequencedRing<>(capacity);
    }

    @Override
    public void accept(Envelope e) {
        envelopes.append(e);
    }

    public List<SequencedRing.Entry<Envelope>> since(long afterSeq, int max, Predicate<Envelope> filter) {
        return envelopes.since(afterSeq, max, filter);
    }

    public long version() {
        return envelopes.version();
    }

    public int size() {
        return envelopes.size();
    }

    public int capacity() {
        return envelopes.capacity();
    }

    /** Drops what is kept; sequence numbers go on (views following the log see only what comes next). */
    public void forget() {
        envelopes.forget();
    }
}
