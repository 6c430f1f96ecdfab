package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

/** What a link publishes, alone: requests, replies, unreadable replies and connection events, on a fake clock. */
class LinkTrafficTest {

    private static final InetSocketAddress PEER = InetSocketAddress.createUnresolved("nao", 9559);

    @Test
    void eachKindOfTrafficBecomesOneEnvelopeOnTheHandedClock() {
        List<Envelope> out = new ArrayList<>();
        long[] now = {5_000_000};
        try (NaoEnvelopeChannel channel = new NaoEnvelopeChannel(out::add)) {
            LinkTraffic traffic = new LinkTraffic(channel, PEER, () -> now[0]);
            HAWActorRPCRequest request = HAWActorRPCRequest.newBuilder().setModule("Test").setMethod("echo").build();
            traffic.request(NaoCall.of("Test", "echo"), request, request.toByteArray());
            now[0] += 10;
            HAWActorRPCResponse response = HAWActorRPCResponse.newBuilder().setError("no").build();
            traffic.reply("stray", response, response.toByteArray());
            traffic.malformed(new byte[] {1, 2}, "3 frames expected");
            traffic.event(ConnectionState.LOST, "nao nao:9559 lost: disconnected");
        }

        assertEquals(4, out.size());
        Envelope sent = out.get(0);
        assertEquals(Direction.OUT, sent.direction());
        assertEquals(Channel.NAO_RPC, sent.channel());
        assertEquals("Test.echo", sent.kind());
        assertEquals(5_000_000, sent.timeMicros());
        assertSame(PEER, sent.peer());
        assertEquals("stray", out.get(1).kind());
        assertEquals(5_000_010, out.get(1).timeMicros());
        assertEquals("malformed", out.get(2).kind());
        assertEquals("3 frames expected", out.get(2).error());
        Envelope event = out.get(3);
        assertEquals(Channel.LINK_EVENT, event.channel());
        assertEquals("nao.lost", event.kind());
        assertArrayEquals("nao nao:9559 lost: disconnected".getBytes(StandardCharsets.UTF_8), event.raw());
    }
}
