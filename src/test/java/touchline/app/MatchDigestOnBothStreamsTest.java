package touchline.app;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A match digest comes apart in front of the read models of the stream it arrives on: a live
 * digest's Status and items reach the live robots and stores (and the debug rule measures it), a
 * replayed one reaches the replay's robots and stores only (and the debug rule never sees it).
 */
class MatchDigestOnBothStreamsTest {

    private static Envelope digest(int robot, long timeMicros) {
        Fumanoid.Status status = Fumanoid.Status.newBuilder().setTimestamp(1).setTeamID(13).setGameState("PLAYING").build();
        Fumanoid.Message field = Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.fieldObjects,
                Fumanoid.FieldObjects.newBuilder().setOption("demo.field")
                        .addObjects(Fumanoid.RelativeObject.newBuilder().setLabel("ball").setX(1200f).setY(-300f))
                        .build()).build();
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.matchDigest,
                Fumanoid.MatchDigest.newBuilder().setStatus(status).addItems(field).build()).build();
        return new Envelope(timeMicros, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 4000 + robot),
                robot, "matchDigest", m, m.toByteArray(), null);
    }

    @Test
    void aLiveDigestUnpacksIntoTheLiveModelsAndAReplayedOneIntoTheReplays() {
        try (Console console = new Console(ConsoleConfig.defaults())) {
            LiveField f = console.field();
            long now = f.clock().nowMicros();
            f.bus().accept(digest(3, now));
            assertEquals("PLAYING", f.robots().robot(3, Origin.LIVE).orElseThrow().gameState());
            assertTrue(f.stores().live().latest().get(3, "demo.field").isPresent(), "the live field shows the item");
            assertTrue(f.matchRule().reading(3).inPlay(), "the rule measures the live digest");

            f.replayStream().publisher().accept(digest(4, now));
            assertEquals("PLAYING", f.robots().robot(4, Origin.REPLAY).orElseThrow().gameState());
            assertTrue(f.stores().replay().latest().get(4, "demo.field").isPresent(), "the replay's field shows the item");
            assertFalse(f.stores().live().latest().get(4, "demo.field").isPresent(), "the live stores never see it");
            assertFalse(f.robots().robot(4, Origin.LIVE).isPresent());
            assertFalse(f.matchRule().reading(4).inPlay(), "a replay's packets are last match's: not measured");
        }
    }
}
