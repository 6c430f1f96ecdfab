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
 * One check on the HTTP request that asks for the WebSocket upgrade: a request it admits goes
 * on and the gate leaves the pipeline; one it refuses gets {@code status} with the sentence
 * why, a closed connection, and is counted under {@code reason}.
 */
abstract class UpgradeGate extends ChannelInboundHandlerAdapter {

    private final Refusals refusals;
    private final Refusals.Reason reason;
    private final HttpResponseStatus status;

    UpgradeGate(Refusals refusals, Refusals.Reason reason, HttpResponseStatus status) {
        this.refusals = refusals;
        this.reason = reason;
        this.status = status;
    }

    /** Why {@code request} is refused, a sentence for whoever sent it; null to admit it. */
    abstract String refusal(FullHttpRequest request);

    @Override
    public final void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (!(msg instanceof FullHttpRequest request)) {
            ctx.fireChannelRead(msg);
            return;
        }
        String why = refusal(request);
        if (why == null) {
            ctx.pipeline().remove(this);
            ctx.fireChannelRead(msg);
            return;
        }
        request.release();
        refusals.count(reason);
        FullHttpResponse response = new DefaultFullHttpResponse(HttpVersion.HTTP_1_1, status,
                Unpooled.copiedBuffer(why + "\n", StandardCharsets.UTF_8));
        response.headers().set(HttpHeaderNames.CONTENT_TYPE, "text/plain; charset=utf-8");
        response.headers().setInt(HttpHeaderNames.CONTENT_LENGTH, response.content().readableBytes());
        ctx.writeAndFlush(response).addListener(ChannelFutureListener.CLOSE);
    }
}
