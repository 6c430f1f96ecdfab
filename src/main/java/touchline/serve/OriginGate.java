package touchline.serve;

import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.handler.codec.http.DefaultFullHttpResponse;
import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.FullHttpResponse;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpResponseStatus;
import io.netty.handler.codec.http.HttpVersion;

import java.nio.charset.StandardCharsets;

/**
 * Admits the WebSocket upgrade of a tool (no {@code Origin} header: Foxglove's and Lichtblick's
 * desktop apps, scripts, another Touchline) or of a web page whose origin is allowed
 * ({@link AllowedOrigins}); any other web page open in the laptop's browser gets 403 and a
 * closed connection, counted, so it cannot read the team's stream from {@code ws://127.0.0.1}.
 * Leaves the pipeline once a request is admitted.
 */
final class OriginGate extends ChannelInboundHandlerAdapter {

    private final AllowedOrigins allowed;
    private final Refusals refusals;

    OriginGate(AllowedOrigins allowed, Refusals refusals) {
        this.allowed = allowed;
        this.refusals = refusals;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (!(msg instanceof FullHttpRequest request)) {
            ctx.fireChannelRead(msg);
            return;
        }
        String origin = request.headers().get(HttpHeaderNames.ORIGIN);
        if (origin == null || allowed.admits(origin)) {
            ctx.pipeline().remove(this);
            ctx.fireChannelRead(msg);
            return;
        }
        request.release();
        refusals.count(Refusals.Reason.ORIGIN);
        FullHttpResponse response = new DefaultFullHttpResponse(HttpVersion.HTTP_1_1, HttpResponseStatus.FORBIDDEN,
                Unpooled.copiedBuffer("a web page from " + AllowedOrigins.clip(origin) + " may not watch this Touchline"
                        + " (start serve with --allow-origin " + AllowedOrigins.clip(origin) + " to allow it)\n",
                        StandardCharsets.UTF_8));
        response.headers().set(HttpHeaderNames.CONTENT_TYPE, "text/plain; charset=utf-8");
        response.headers().setInt(HttpHeaderNames.CONTENT_LENGTH, response.content().readableBytes());
        ctx.writeAndFlush(response).addListener(ChannelFutureListener.CLOSE);
    }
}
