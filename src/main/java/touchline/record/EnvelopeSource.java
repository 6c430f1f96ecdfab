package touchline.record;

import touchline.transport.EnvelopeSink;

/**
 * Something that publishes live Envelopes into a sink until closed: the hook through which
 * the headless recorder gets its traffic (the application wires in its UDP/ZeroMQ transports).
 */
@FunctionalInterface
public interface EnvelopeSource {
    AutoCloseable start(EnvelopeSink sink) throws Exception;
}
