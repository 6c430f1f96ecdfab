package touchline.transport;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;

import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

/** {@link Envelope#extension}: the kind the decoder gave and the message have to agree. */
class EnvelopeTest {

    private final MessageCodec codec = new MessageCodec(new MessageKinds());

    private Envelope decoded(Fumanoid.Message m) {
        MessageResult.Decoded d = (MessageResult.Decoded) codec.decode(m.toByteArray());
        return new Envelope(1, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 3838), m.getRobotID(),
                d.kind(), d.message(), m.toByteArray(), null);
    }

    @Test
    void givesTheExtensionOfTheDecodedKindOnly() {
        Envelope e = decoded(Fumanoid.Message.newBuilder().setRobotID(3)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).setGameState("PLAYING").build())
                .build());
        assertEquals("PLAYING", e.extension(Fumanoid.status).getGameState());
        assertNull(e.extension(Fumanoid.debugText));
        Envelope text = decoded(Fumanoid.Message.newBuilder().setRobotID(3)
                .setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("demo.text").setText("hi").build())
                .build());
        assertEquals("hi", text.extension(Fumanoid.debugText).getText());
        assertNull(text.extension(Fumanoid.status));
    }

    @Test
    void aKindThatDisagreesWithTheMessageGivesNothing() {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(3)
                .setExtension(Fumanoid.status, Fumanoid.Status.getDefaultInstance()).build();
        Envelope wrong = new Envelope(1, Direction.IN, Channel.FUMANOID, null, 3, "debugText", m, m.toByteArray(), null);
        assertNull(wrong.extension(Fumanoid.debugText), "the message has no debugText");
        assertNull(wrong.extension(Fumanoid.status), "the kind says it is not a status");
        Envelope raw = new Envelope(1, Direction.IN, Channel.GAMECONTROLLER, null, Envelope.NO_ROBOT, "status", null,
                new byte[4], null);
        assertNull(raw.extension(Fumanoid.status), "no message");
    }
}
