package touchline.transport.nao;

import com.google.protobuf.Message;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.MicrosClock;

import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;

/**
 * What a NAO link puts into the console's Envelope stream: each request (OUT), each reply
 * (IN, named after its call, "stray" or "malformed") and each connection event ({@link
 * Channel#LINK_EVENT}, "nao.online"...), stamped with the console's wall clock and published
 * through the link's {@link NaoEnvelopeChannel}.
 */
final class LinkTraffic {

    private final NaoEnvelopeChannel envelopes;
    private final InetSocketAddress peer;
    private final MicrosClock clock;

    LinkTraffic(NaoEnvelopeChannel envelopes, InetSocketAddress peer, MicrosClock clock) {
        this.envelopes = envelopes;
        this.peer = peer;
        this.clock = clock;
    }

    void request(NaoCall call, HAWActorRPCRequest request, byte[] payload) {
        publish(Direction.OUT, Channel.NAO_RPC, call.qualifiedName(), request, payload, null);
    }

    /** @param kind the call's qualified name, or "stray" when no call waits for it */
    void reply(String kind, HAWActorRPCResponse response, byte[] payload) {
        publish(Direction.IN, Channel.NAO_RPC, kind, response, payload, null);
    }

    void malformed(byte[] payload, String why) {
        publish(Direction.IN, Channel.NAO_RPC, "malformed", null, payload, why);
    }

    /** A change of the connection's state, {@code text} in words (also logged). */
    void event(ConnectionState state, String text) {
        publish(Direction.IN, Channel.LINK_EVENT, "nao." + state.name().toLowerCase(), null,
                text.getBytes(StandardCharsets.UTF_8), null);
    }

    private void publish(Direction direction, Channel channel, String kind, Message message,
                         byte[] payload, String error) {
        envelopes.publish(new Envelope(clock.nowMicros(), direction, channel, peer, Envelope.NO_ROBOT, kind, message,
                payload, error));
    }
}
