package touchline.transport;

import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.socket.DatagramPacket;
import io.netty.handler.codec.MessageToMessageDecoder;
import touchline.protocol.DatagramClass;

import java.util.List;

/** Time-stamps each datagram and tells FUmanoids, GameController and reliable-stream traffic apart. */
final class DatagramDemultiplexer extends MessageToMessageDecoder<DatagramPacket> {

    private final MicrosClock clock;

    DatagramDemultiplexer(MicrosClock clock) {
        this.clock = clock;
    }

    @Override
    protected void decode(ChannelHandlerContext ctx, DatagramPacket packet, List<Object> out) {
        byte[] bytes = ByteBufUtil.getBytes(packet.content());
        out.add(new ReceivedDatagram(clock.nowMicros(), packet.sender(), bytes, DatagramClass.of(bytes, bytes.length)));
    }
}
