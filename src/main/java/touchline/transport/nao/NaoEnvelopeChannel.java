package touchline.transport.nao;

import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

/**
 * The way NAO traffic enters the console's Envelope stream. JeroMQ owns its sockets and threads,
 * and two of them (RPC and camera) publish here: publishing is serialised, so the stream sees
 * one NAO's envelopes one at a time, in the order they were published. A sink that fails loses
 * that envelope only (said in the log); after {@link #close} nothing more is published.
 */
public final class NaoEnvelopeChannel implements AutoCloseable {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(NaoEnvelopeChannel.class);

    private final EnvelopeSink sink;
    private boolean open = true; // guarded by this

    public NaoEnvelopeChannel(EnvelopeSink sink) {
        this.sink = sink;
    }

    public synchronized void publish(Envelope envelope) {
        if (!open) {
            return;
        }
        try {
            sink.accept(envelope);
        } catch (RuntimeException e) {
            LOG.warn("NAO envelope {} not published: {}", envelope.kind(), e.toString());
        }
    }

    @Override
    public synchronized void close() {
        open = false;
    }
}
