package touchline.transport;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;

/** The end of an inbound pipeline (UDP, or the NAO link's embedded channel): hands each Envelope to the stream. */
@io.netty.channel.ChannelHandler.Sharable
public final class EnvelopePublisher extends SimpleChannelInboundHandler<Envelope> {

    private final EnvelopeSink sink;

    public EnvelopePublisher(EnvelopeSink sink) {
        this.sink = sink;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, Envelope envelope) {
        sink.accept(envelope);
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        // A handler or sink failure must not close the channel; this envelope is lost, the next one is not.
        org.slf4j.LoggerFactory.getLogger(EnvelopePublisher.class).warn("inbound pipeline: {}", cause.toString());
    }
}
