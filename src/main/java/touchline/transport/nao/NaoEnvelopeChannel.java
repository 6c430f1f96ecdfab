package touchline.transport.nao;

import io.netty.channel.ChannelPipeline;
import io.netty.channel.embedded.EmbeddedChannel;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

/**
 * The Netty pipeline NAO traffic passes through on its way into the console's Envelope
 * stream. JeroMQ owns its sockets and threads, so there is no Netty socket channel to read
 * from; instead the JeroMQ threads (RPC and camera) write each {@link Envelope} into an
 * {@link EmbeddedChannel}, whose handlers run synchronously on the writing thread. The last
 * handler, named {@value #PUBLISHER}, hands the envelope to the {@link EnvelopeSink}. The
 * same accounting or decoding handlers used for the UDP traffic can therefore be attached
 * with {@code pipeline().addBefore(PUBLISHER, name, handler)}. Writes are serialised because
 * an EmbeddedChannel is not thread-safe and two JeroMQ threads feed it.
 */
public final class NaoEnvelopeChannel implements AutoCloseable {

    public static final String PUBLISHER = "publish";

    private final EmbeddedChannel channel;

    public NaoEnvelopeChannel(EnvelopeSink sink) {
        channel = new EmbeddedChannel();
        channel.pipeline().addLast(PUBLISHER, new touchline.transport.EnvelopePublisher(sink));
    }

    /** For attaching shared handlers before {@link #PUBLISHER}. */
    public ChannelPipeline pipeline() {
        return channel.pipeline();
    }

    public synchronized void publish(Envelope envelope) {
        if (channel.isOpen()) {
            channel.writeInbound(envelope);
        }
    }

    @Override
    public synchronized void close() {
        channel.finishAndReleaseAll();
    }
}
