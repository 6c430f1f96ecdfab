package touchline.serve;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import io.netty.util.AttributeKey;

import java.util.List;

/**
 * A viewer's life on its connection: joins the table (server info and channels) when the
 * WebSocket handshake completes, sends what waits when the socket becomes writable again, and
 * leaves (ending its subscriptions) when the connection closes for any reason.
 */
final class ViewerSession extends ChannelInboundHandlerAdapter {

    static final AttributeKey<Viewer> VIEWER = AttributeKey.valueOf("touchline.viewer");

    private final ChannelTable channels;
    private final ViewerTable viewers;
    private final FoxgloveFrames frames;
    private final ServeConfig config;
    private final Refusals refusals;
    private final Admission admission;

    ViewerSession(ChannelTable channels, ViewerTable viewers, FoxgloveFrames frames, ServeConfig config,
                  Refusals refusals, Admission admission) {
        this.channels = channels;
        this.viewers = viewers;
        this.frames = frames;
        this.config = config;
        this.refusals = refusals;
        this.admission = admission;
    }

    @Override
    public void userEventTriggered(ChannelHandlerContext ctx, Object evt) throws Exception {
        if (evt instanceof WebSocketServerProtocolHandler.HandshakeComplete) {
            admission.upgraded(ctx.channel()); // a viewer may read without ever sending anything
            if (viewers.size() >= config.maxViewers()) {
                refusals.count(Refusals.Reason.VIEWERS);
                ctx.writeAndFlush(frames.status(FoxgloveFrames.STATUS_ERROR, "too many viewers (" + config.maxViewers()
                        + " at once); try again later")).addListener(io.netty.channel.ChannelFutureListener.CLOSE);
                return;
            }
            List<String> raw = new io.netty.handler.codec.http.QueryStringDecoder(
                    ((WebSocketServerProtocolHandler.HandshakeComplete) evt).requestUri()).parameters()
                    .getOrDefault(Viewer.BYTES_PARAMETER, List.of());
            boolean webPage = ((WebSocketServerProtocolHandler.HandshakeComplete) evt).requestHeaders()
                    .contains(io.netty.handler.codec.http.HttpHeaderNames.ORIGIN);
            Viewer v = new Viewer(ctx.channel(), frames, config.queueLimit(), raw.contains("1"), webPage);
            ctx.channel().attr(VIEWER).set(v);
            channels.welcome(v);
        }
        super.userEventTriggered(ctx, evt);
    }

    @Override
    public void channelWritabilityChanged(ChannelHandlerContext ctx) throws Exception {
        Viewer v = ctx.channel().attr(VIEWER).get();
        if (v != null && ctx.channel().isWritable()) {
            v.drain();
        }
        super.channelWritabilityChanged(ctx);
    }

    @Override
    public void channelInactive(ChannelHandlerContext ctx) throws Exception {
        Viewer v = ctx.channel().attr(VIEWER).getAndSet(null);
        if (v != null) {
            viewers.remove(v);
            v.leave();
        }
        super.channelInactive(ctx);
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        // a broken connection or a frame the codec refused: this viewer goes, nobody else notices
        ctx.close();
    }
}
