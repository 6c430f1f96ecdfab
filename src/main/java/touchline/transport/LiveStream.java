package touchline.transport;

import java.util.concurrent.atomic.LongAdder;

/**
 * The live field's envelopes: what the transports hear and send, the console's own sending,
 * and a remote Touchline's stream when this console views one. Everything that acts on the
 * field (debug-option switches, match mode, the budget guard, senders) and the recorder and
 * live server subscribe here, and only here: a replay has its own {@link ReplayStream}, of
 * another type, so it cannot be handed to them. An envelope marked replayed is refused
 * (counted, logged once) rather than taken as live.
 */
public final class LiveStream implements EnvelopeSink, EnvelopeSource {

    private final EnvelopeBus bus = new EnvelopeBus();
    private final LongAdder refusedReplayed = new LongAdder();

    @Override
    public AutoCloseable subscribe(EnvelopeSink sink) {
        return bus.subscribe(sink);
    }

    @Override
    public void accept(Envelope envelope) {
        if (envelope.replayed()) {
            refusedReplayed.increment();
            if (refusedReplayed.sum() == 1) {
                org.slf4j.LoggerFactory.getLogger(LiveStream.class)
                        .warn("a replayed envelope was offered to the live stream and refused: {}", envelope);
            }
            return;
        }
        bus.accept(envelope);
    }

    /** Replayed envelopes offered here and refused (a replay publishes into its {@link ReplayStream}). */
    public long refusedReplayed() {
        return refusedReplayed.sum();
    }

    public long subscriberFailures() {
        return bus.subscriberFailures();
    }
}
