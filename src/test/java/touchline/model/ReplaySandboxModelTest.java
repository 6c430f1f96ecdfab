package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;
import touchline.transport.SendResult;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A replay beside the live field, in the model: a replayed robot with a live robot's number is
 * a second robot (online by the replay's clock), and nothing it plays makes the option session
 * send, while the live robot's requests go out as before.
 */
class ReplaySandboxModelTest {

    private final long[] now = {1_000_000_000L};
    private final long[] replayNow = {5_000_000L};
    private final List<String> sent = new ArrayList<>();
    private final MessageCodec codec = new MessageCodec(new MessageKinds());
    private final DebugOptionSession session = new DebugOptionSession((id, m) -> {
        sent.add(id + ":" + (m.hasExtension(Fumanoid.debugOptionListRequest) ? "list?"
                : m.getExtension(Fumanoid.debugOptionRequest).getName()));
        return SendResult.sent();
    }, codec, () -> now[0], () -> replayNow[0]);
    private final RobotRegistry registry = new RobotRegistry(() -> now[0], () -> replayNow[0],
            RobotRegistry.DEFAULT_OFFLINE_AFTER_MICROS);

    {
        registry.addPresenceListener(session);
    }

    private Envelope envelope(long time, int robot, Fumanoid.Message.Builder m) {
        Fumanoid.Message built = m.setRobotID(robot).build();
        String kind = ((MessageResult.Decoded) codec.decode(built.toByteArray())).kind();
        return new Envelope(time, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 4000 + robot),
                robot, kind, built, built.toByteArray(), null);
    }

    /** As the console's two streams hand it on: a replayed envelope to the replay's read models, any other to the live side. */
    private void receive(Envelope e) {
        if (e.replayed()) {
            registry.replay().accept(e);
            session.replayed().accept(e);
        } else {
            registry.live().accept(e);
            session.accept(e);
        }
    }

    private Envelope status(long time, int robot, String gameState) {
        return envelope(time, robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setRobotName("fu" + robot).setGameState(gameState).build()));
    }

    private Envelope list(long time, int robot, String option) {
        return envelope(time, robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.debugOptionList,
                Fumanoid.DebugOptionList.newBuilder().addOptions(Fumanoid.DebugOption.newBuilder().setName(option)
                        .setKind(Fumanoid.DebugKind.TEXT_VALUE)).build()));
    }

    private Envelope text(long time, int robot, String option) {
        return envelope(time, robot, Fumanoid.Message.newBuilder().setExtension(Fumanoid.debugText,
                Fumanoid.DebugText.newBuilder().setOption(option).setText("hi").build()));
    }

    @Test
    void aReplayedRobotWithALiveRobotsNumberIsASecondRobot() {
        receive(status(now[0], 3, "INITIAL"));
        receive(status(replayNow[0], 3, "PLAYING").asReplayed());
        receive(status(replayNow[0] + 1, 3, "PLAYING").asReplayed());

        RobotSnapshot live = registry.robot(3).orElseThrow();
        RobotSnapshot replayed = registry.robot(3, Origin.REPLAY).orElseThrow();
        assertEquals("INITIAL", live.gameState(), "the replay does not overwrite the live robot");
        assertEquals(1, live.packets());
        assertEquals("PLAYING", replayed.gameState());
        assertEquals(2, replayed.packets());
        assertEquals("fu3", live.label());
        assertEquals("fu3 (replay)", replayed.label());
        assertEquals(List.of(Origin.LIVE, Origin.REPLAY), registry.robots().stream().map(RobotSnapshot::origin).toList());
    }

    @Test
    void aRecordingsBadSenderIsCountedApartFromTheLiveSenderAtTheSameAddress() {
        receive(status(now[0], 3, "INITIAL"));
        Envelope junk = new Envelope(replayNow[0], Direction.IN, Channel.FUMANOID,
                new InetSocketAddress("127.0.0.1", 4003), Envelope.NO_ROBOT, "malformed", null, new byte[3], "too short");
        registry.replay().accept(junk.asReplayed());

        assertEquals(0, registry.robot(3).orElseThrow().malformed(), "the live robot at that address sent nothing bad");
        assertEquals(List.of("/127.0.0.1:4003 (replay)"), registry.sources().stream()
                .filter(s -> s.malformed() > 0).map(SourceSnapshot::label).toList());
        assertEquals(0, registry.sources().get(0).malformed());
        registry.forgetReplayed();
        assertEquals(List.of(Origin.LIVE), registry.sources().stream().map(SourceSnapshot::origin).toList());
    }

    @Test
    void aReplayedRobotIsOnlineByTheReplaysClockAndForgottenWithoutTouchingTheLiveOne() {
        receive(status(now[0], 3, "INITIAL"));
        receive(status(replayNow[0], 3, "PLAYING").asReplayed());
        now[0] += 10 * RobotRegistry.DEFAULT_OFFLINE_AFTER_MICROS; // only the wall clock moves
        receive(status(now[0], 3, "INITIAL"));
        registry.tick();
        assertTrue(registry.robot(3, Origin.REPLAY).orElseThrow().online(), "the replay's clock stood still");
        replayNow[0] += 2 * RobotRegistry.DEFAULT_OFFLINE_AFTER_MICROS;
        registry.tick();
        assertFalse(registry.robot(3, Origin.REPLAY).orElseThrow().online());
        assertTrue(registry.robot(3).orElseThrow().online());

        registry.forgetReplayed();
        assertTrue(registry.robot(3, Origin.REPLAY).isEmpty());
        assertEquals(2, registry.robot(3).orElseThrow().packets());
    }

    @Test
    void nothingAReplayPlaysMakesTheOptionSessionSend() {
        receive(status(now[0], 3, "INITIAL"));
        receive(list(now[0], 3, "demo.text"));
        session.setWanted(3, "demo.text", true);
        receive(text(now[0], 3, "demo.text"));
        sent.clear();

        // a replayed robot 3 (the live one's number) and robot 5 (not on the field) appear,
        // send option lists without the wanted option switched on, and go quiet
        receive(status(replayNow[0], 3, "PLAYING").asReplayed());
        receive(status(replayNow[0], 5, "PLAYING").asReplayed());
        receive(list(replayNow[0], 3, "demo.text").asReplayed());
        receive(list(replayNow[0], 5, "demo.plot").asReplayed());
        receive(text(replayNow[0], 5, "demo.plot").asReplayed());
        now[0] += 10 * DebugOptionSession.STREAMING_WINDOW_MICROS;
        receive(status(now[0], 3, "INITIAL"));
        receive(text(now[0], 3, "demo.text"));
        assertTrue(session.options(5, Origin.REPLAY).option("demo.plot").orElseThrow().streaming(),
                "streaming by the replay's clock, whatever the wall clock says");
        replayNow[0] += 10 * RobotRegistry.DEFAULT_OFFLINE_AFTER_MICROS;
        registry.tick();
        session.tick();

        // the live robot's request still goes out, and it is the only one
        session.setWanted(3, "demo.other", true);
        assertEquals(List.of("3:demo.other"), sent);
        assertEquals(List.of("demo.text"), session.options(3, Origin.REPLAY).options().stream()
                .map(OptionState::name).toList(), "the replayed robot's options are shown apart");
        assertFalse(session.options(5).listReceived(), "robot 5 is not on the field");
        assertEquals(List.of("demo.text"), session.options(3).options().stream().map(OptionState::name).toList());

        session.forgetReplayed();
        assertFalse(session.options(3, Origin.REPLAY).listReceived());
        assertTrue(session.options(3).listReceived());
    }
}
