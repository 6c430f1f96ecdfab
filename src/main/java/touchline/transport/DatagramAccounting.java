package touchline.transport;

import io.netty.channel.ChannelHandler;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.channel.socket.DatagramPacket;

/** Counts inbound datagrams and bytes; passes everything on unchanged. */
@ChannelHandler.Sharable
final class DatagramAccounting extends ChannelInboundHandlerAdapter {

    private final TrafficCounters counters;

    DatagramAccounting(TrafficCounters counters) {
        this.counters = counters;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (msg instanceof DatagramPacket packet) {
            counters.countIn(packet.content().readableBytes());
        }
        ctx.fireChannelRead(msg);
    }
}
