package touchline.transport;

/**
 * A recording's envelopes as a replay plays them, apart from the {@link LiveStream}: the read
 * models the views show (robots, option lists, stores, NAO feeds) have an instance subscribed
 * here, and nothing that acts on the field does. It is deliberately not an {@link EnvelopeSink}:
 * a sender or a transport, which take a sink to publish into, cannot be handed it; the player
 * publishes through {@link #publisher()}, which marks every envelope replayed.
 * {@code ArchitectureTest} keeps the type out of the senders, match mode and the options switch.
 */
public final class ReplayStream implements EnvelopeSource {

    private final EnvelopeBus bus = new EnvelopeBus();
    private final EnvelopeSink publisher = e -> bus.accept(e.asReplayed());

    @Override
    public AutoCloseable subscribe(EnvelopeSink sink) {
        return bus.subscribe(sink);
    }

    /** Where a replay's player publishes: every envelope goes on marked {@linkplain Envelope#asReplayed() replayed}. */
    public EnvelopeSink publisher() {
        return publisher;
    }

    public long subscriberFailures() {
        return bus.subscriberFailures();
    }
}
