package touchline.transport;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.channel.socket.DatagramPacket;
import touchline.protocol.DatagramClass;
import touchline.security.InboundVerifier;

/**
 * The first inbound step: counts each datagram, time-stamps it, copies its bytes off the
 * socket buffer (releasing it at once) and tells FUmanoids, GameController and
 * reliable-stream traffic apart. One handler rather than one per step because this runs for
 * every datagram at up to half a million a second, where each extra pipeline hop shows.
 */
final class DatagramIntake extends ChannelInboundHandlerAdapter {

    private final TrafficCounters counters;
    private final MicrosClock clock;

    DatagramIntake(TrafficCounters counters, MicrosClock clock) {
        this.counters = counters;
        this.clock = clock;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (!(msg instanceof DatagramPacket packet)) {
            ctx.fireChannelRead(msg);
            return;
        }
        byte[] bytes;
        try {
            var content = packet.content();
            bytes = new byte[content.readableBytes()];
            content.getBytes(content.readerIndex(), bytes);
        } finally {
            packet.release();
        }
        counters.countIn(bytes.length);
        // classified without an authentication trailer: it would hide the length header
        ctx.fireChannelRead(new ReceivedDatagram(clock.nowMicros(), packet.sender(), bytes,
                DatagramClass.of(bytes, InboundVerifier.payloadLength(bytes))));
    }
}
