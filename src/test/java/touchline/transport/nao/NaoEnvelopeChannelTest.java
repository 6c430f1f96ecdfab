package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;

class NaoEnvelopeChannelTest {

    private static Envelope envelope(String kind) {
        return new Envelope(1, Direction.IN, Channel.NAO_RPC, null, Envelope.NO_ROBOT, kind, null, new byte[0], null);
    }

    @Test
    void aFailingSinkLosesOnlyThatEnvelopeAndNothingIsPublishedAfterClose() {
        List<Envelope> seen = new CopyOnWriteArrayList<>();
        NaoEnvelopeChannel channel = new NaoEnvelopeChannel(e -> {
            if (e.kind().equals("boom")) {
                throw new IllegalStateException("sink failed");
            }
            seen.add(e);
        });
        channel.publish(envelope("a"));
        channel.publish(envelope("boom"));
        channel.publish(envelope("b"));
        channel.close();
        channel.publish(envelope("after close"));
        assertEquals(List.of("a", "b"), seen.stream().map(Envelope::kind).toList());
    }
}
