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
import io.netty.handler.codec.http.QueryStringDecoder;

import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Admits an HTTP request (the WebSocket upgrade) only with the server's token in its query,
 * {@code ?token=…}; anything else gets 401 and a closed connection, and is counted. Leaves the
 * pipeline once a request is admitted.
 */
final class TokenGate extends ChannelInboundHandlerAdapter {

    private final AccessToken token;
    private final Refusals refusals;

    TokenGate(AccessToken token, Refusals refusals) {
        this.token = token;
        this.refusals = refusals;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (!(msg instanceof FullHttpRequest request)) {
            ctx.fireChannelRead(msg);
            return;
        }
        List<String> presented = new QueryStringDecoder(request.uri()).parameters().get("token");
        if (presented != null && presented.size() == 1 && token.admits(presented.get(0))) {
            ctx.pipeline().remove(this);
            ctx.fireChannelRead(msg);
            return;
        }
        request.release();
        refusals.count(Refusals.Reason.TOKEN);
        FullHttpResponse response = new DefaultFullHttpResponse(HttpVersion.HTTP_1_1, HttpResponseStatus.UNAUTHORIZED,
                Unpooled.copiedBuffer("this Touchline needs its token: ws://HOST:PORT/?token=...\n", StandardCharsets.UTF_8));
        response.headers().set(HttpHeaderNames.CONTENT_TYPE, "text/plain; charset=utf-8");
        response.headers().setInt(HttpHeaderNames.CONTENT_LENGTH, response.content().readableBytes());
        ctx.writeAndFlush(response).addListener(ChannelFutureListener.CLOSE);
    }
}
