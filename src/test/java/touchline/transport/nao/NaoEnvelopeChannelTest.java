package touchline.transport.nao;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertEquals;

class NaoEnvelopeChannelTest {

    private static Envelope envelope(String kind) {
        return new Envelope(1, Direction.IN, Channel.NAO_RPC, null, Envelope.NO_ROBOT, kind, null, new byte[0], null);
    }

    @Test
    void attachedHandlersSeeEveryEnvelopeBeforeTheSinkAndAFailingSinkDoesNotStopTheChannel() {
        List<Envelope> seen = new CopyOnWriteArrayList<>();
        AtomicInteger counted = new AtomicInteger();
        try (NaoEnvelopeChannel channel = new NaoEnvelopeChannel(e -> {
            if (e.kind().equals("boom")) {
                throw new IllegalStateException("sink failed");
            }
            seen.add(e);
        })) {
            channel.pipeline().addBefore(NaoEnvelopeChannel.PUBLISHER, "count", new ChannelInboundHandlerAdapter() {
                @Override
                public void channelRead(ChannelHandlerContext ctx, Object msg) {
                    counted.incrementAndGet();
                    ctx.fireChannelRead(msg);
                }
            });
            channel.publish(envelope("a"));
            channel.publish(envelope("boom"));
            channel.publish(envelope("b"));
        }
        assertEquals(3, counted.get());
        assertEquals(List.of("a", "b"), seen.stream().map(Envelope::kind).toList());
    }
}
