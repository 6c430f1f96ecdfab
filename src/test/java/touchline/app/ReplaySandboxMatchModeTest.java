package touchline.app;

import org.junit.jupiter.api.Test;
import touchline.game.ManualClock;
import touchline.app.game.MatchMode;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.*;

/** Robots in a recording that reported PLAYING never silence the live console; live robots do. */
class ReplaySandboxMatchModeTest {

    private final MatchMode matchMode = new MatchMode(new ManualClock(1_000));
    /** As the console wires it: the reported game state listens to the live stream only. */
    private final touchline.transport.LiveStream reported = new touchline.transport.LiveStream();

    {
        reported.subscribe(new ReportedGameState(matchMode));
    }

    private static Envelope playing(int robot) {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setGameState("PLAYING").build()).build();
        return new Envelope(1, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 4000 + robot), robot,
                "status", m, m.toByteArray(), null);
    }

    @Test
    void aReplayedRobotReportingPlayingDoesNotChangeMatchMode() {
        reported.accept(playing(3).asReplayed());
        assertTrue(matchMode.mayConsoleSend());
        assertFalse(matchMode.playIsOn());
        assertEquals("", matchMode.notice());
    }

    @Test
    void aLiveRobotReportingPlayingStillSilencesTheConsole() {
        reported.accept(playing(3).asReplayed());
        reported.accept(playing(3));
        assertFalse(matchMode.mayConsoleSend());
        assertTrue(matchMode.notice().contains("robot 3"), matchMode.notice());
    }
}
