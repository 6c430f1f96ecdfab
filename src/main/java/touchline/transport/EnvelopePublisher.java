package touchline.transport;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;

/** The end of the inbound pipeline: hands each Envelope to the stream. */
final class EnvelopePublisher extends SimpleChannelInboundHandler<Envelope> {

    private final EnvelopeSink sink;

    EnvelopePublisher(EnvelopeSink sink) {
        this.sink = sink;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, Envelope envelope) {
        sink.accept(envelope);
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        // A handler bug must not close the console's socket; the datagram is lost, the next one is not.
        org.slf4j.LoggerFactory.getLogger(EnvelopePublisher.class).warn("inbound pipeline: {}", cause.toString());
    }
}
