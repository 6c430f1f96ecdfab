package touchline.transport;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A fan-out of envelopes to subscribers, the inside of the console's two streams
 * ({@link LiveStream}, {@link ReplayStream}); a bare one serves tests and benchmarks. A subscriber that throws is reported once per failure
 * and does not stop delivery to the others.
 */
public final class EnvelopeBus implements EnvelopeSink {

    private final List<EnvelopeSink> subscribers = new CopyOnWriteArrayList<>();
    private final java.util.concurrent.atomic.AtomicLong subscriberFailures = new java.util.concurrent.atomic.AtomicLong();

    public AutoCloseable subscribe(EnvelopeSink sink) {
        subscribers.add(sink);
        return () -> subscribers.remove(sink);
    }

    @Override
    public void accept(Envelope envelope) {
        for (EnvelopeSink sink : subscribers) {
            try {
                sink.accept(envelope);
            } catch (RuntimeException e) {
                if (subscriberFailures.getAndIncrement() == 0) {
                    org.slf4j.LoggerFactory.getLogger(EnvelopeBus.class)
                            .warn("a subscriber failed on {}: {}", envelope, e.toString());
                }
            }
        }
    }

    public long subscriberFailures() {
        return subscriberFailures.get();
    }
}
