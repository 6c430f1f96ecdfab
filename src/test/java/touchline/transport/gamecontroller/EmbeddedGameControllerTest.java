package touchline.transport.gamecontroller;

import touchline.app.game.EmbeddedGameController;

import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.game.ManualClock;
import touchline.app.game.MatchMode;
import touchline.game.Penalty;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.ReturnPacket;
import touchline.testing.HeldOwner;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The GameController on loopback: return packets, liveness, manual penalties, rivals, match mode. */
class EmbeddedGameControllerTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private final List<Envelope> envelopes = new CopyOnWriteArrayList<>();
    private final List<String> events = new CopyOnWriteArrayList<>();

    private EmbeddedGameController start(GcProfile profile, InetSocketAddress dest, boolean watchRivals,
                                         MatchMode matchMode) throws Exception {
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        GcConfig config = new GcConfig(profile, false, List.of(dest), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT,
                watchRivals ? ANY_LOOPBACK_PORT : null, 500, false);
        EmbeddedGameController gc = new EmbeddedGameController(game, config, envelopes::add, matchMode,
                new touchline.app.SystemClock());
        gc.addEventListener(events::add);
        gc.start();
        return gc;
    }

    @Test
    void returnPacketsMakeRobotsOnlineAndManualPenaltyIsEdgeTriggered() throws Exception {
        try (LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = start(GcProfile.HL12, robot.address(), false, null)) {
            InetSocketAddress returns = gc.returnAddress();
            assertEquals(RobotLiveness.Status.OFFLINE, gc.liveness().status(7, 2, gc.runtime().now()));
            // starts with MAN_PENALISE: no edge, no penalty (like the Java GameController)
            robot.send(new ReturnPacket.V2(7, 2, ReturnPacket.MAN_PENALISE).encode(), returns);
            Await.until(() -> gc.liveness().status(7, 2, gc.runtime().now()) == RobotLiveness.Status.ONLINE, 2000,
                    "robot 7/2 online");
            assertEquals(Penalty.NONE, gc.runtime().snapshot().hl().team(7).player(2).penalty());
            robot.send(new ReturnPacket.V2(7, 2, ReturnPacket.ALIVE).encode(), returns);
            robot.send(new ReturnPacket.V2(7, 2, ReturnPacket.MAN_PENALISE).encode(), returns);
            Await.until(() -> gc.runtime().snapshot().hl().team(7).player(2).penalty() == Penalty.MANUAL, 2000,
                    "manual penalty");
            // repeating the same message changes nothing; a change to MAN_UNPENALISE lifts it
            robot.send(new ReturnPacket.V2(7, 2, ReturnPacket.MAN_PENALISE).encode(), returns);
            robot.send(new ReturnPacket.V2(7, 2, ReturnPacket.MAN_UNPENALISE).encode(), returns);
            Await.until(() -> gc.runtime().snapshot().hl().team(7).player(2).penalty() == Penalty.NONE, 2000, "unpenalised");
            assertEquals(List.of("unpenalise 7 2", "penalty 7 2 manual"), gc.runtime().snapshot().undoList().subList(0, 2));
            assertTrue(envelopes.stream().anyMatch(e -> e.direction() == Direction.IN
                    && e.kind().equals("gc.return.v2") && e.error() == null));
        }
    }

    @Test
    void malformedReturnPacketsAreCountedPerSourceAndNeverApplied() throws Exception {
        try (LoopbackReceiver robot = new LoopbackReceiver();
             LoopbackReceiver other = new LoopbackReceiver();
             EmbeddedGameController gc = start(GcProfile.HL12, robot.address(), false, null)) {
            InetSocketAddress returns = gc.returnAddress();
            robot.send(new byte[]{'R', 'G', 'r', 't', 2, 7, 2}, returns);              // 7 bytes
            robot.send(new byte[]{'R', 'G', 'r', 't', 9, 7, 2, 0}, returns);           // unknown version
            robot.send(new ReturnPacket.V2(7, 0, ReturnPacket.MAN_PENALISE).encode(), returns);   // player 0
            robot.send(new ReturnPacket.V2(7, 200, ReturnPacket.MAN_PENALISE).encode(), returns); // player 200
            other.send(new ReturnPacket.V4(2, 7, 0, Float.NaN, 0, 0, -1, 0, 0).encode(), returns); // NaN pose
            other.send(new ReturnPacket.V2(99, 1, ReturnPacket.ALIVE).encode(), returns);        // foreign team
            // a good packet afterwards still works
            robot.send(new ReturnPacket.V2(7, 3, ReturnPacket.ALIVE).encode(), returns);
            Await.until(() -> gc.liveness().status(7, 3, gc.runtime().now()) == RobotLiveness.Status.ONLINE, 2000,
                    "good packet applied");
            Await.until(() -> gc.badPackets().total() == 6, 2000, "6 bad packets counted");
            String robotKey = "127.0.0.1:" + robot.address().getPort();
            String otherKey = "127.0.0.1:" + other.address().getPort();
            assertEquals(4, gc.badPackets().bySource().get(robotKey).count());
            assertEquals(2, gc.badPackets().bySource().get(otherKey).count());
            assertTrue(gc.badPackets().bySource().get(otherKey).lastReason().contains("team 99"));
            assertEquals(RobotLiveness.Status.OFFLINE, gc.liveness().status(7, 200, gc.runtime().now()));
            assertEquals(RobotLiveness.Status.OFFLINE, gc.liveness().status(7, 0, gc.runtime().now()));
            assertEquals(Penalty.NONE, gc.runtime().snapshot().hl().team(7).player(2).penalty());
            assertEquals(6, envelopes.stream().filter(e -> e.kind().equals("gc.return.malformed")
                    && e.error() != null).count());
            assertEquals(2, events.stream().filter(e -> e.startsWith("bad return packet")).count(),
                    "one event per bad source, not per packet");
        }
    }

    @Test
    void anotherGameControllerRaisesAWarning() throws Exception {
        try (LoopbackReceiver rival = new LoopbackReceiver();
             EmbeddedGameController gc = start(GcProfile.HL12, ANY_LOOPBACK_PORT, true, null)) {
            // a second GameController sends to our rival-watch port (own packets: see the 2014 test)
            try (EmbeddedGameController self = new EmbeddedGameController(
                    new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock()),
                    new GcConfig(GcProfile.HL12, false, List.of(gc.rivalAddress()), ANY_LOOPBACK_PORT,
                            ANY_LOOPBACK_PORT, null, 500, false), e -> { }, null, new touchline.app.SystemClock())) {
                self.start();
                Await.until(() -> gc.rivals().active(gc.runtime().now()).size() == 1, 2000, "a second GC noticed");
            }
            assertTrue(gc.rivalWarning().contains("ANOTHER GAMECONTROLLER"), gc.rivalWarning());
            Await.until(() -> events.stream().anyMatch(e -> e.contains("ANOTHER GAMECONTROLLER")), 2000,
                    "warning event");
            // a raw rival packet from a plain socket is recognised with its format and state
            GameControlData playing = gc.runtime().snapshot().robots();
            rival.send(new HlGameState12().encode(playing), gc.rivalAddress());
            Await.until(() -> gc.rivals().active(gc.runtime().now()).size() == 2, 2000, "second rival");
            var r = gc.rivals().active(gc.runtime().now()).get("127.0.0.1:" + rival.address().getPort());
            assertEquals("gc.hl12", r.kind());
            assertEquals("13 vs 7", r.teams());
        }
    }

    @Test
    void ownPacketsOnTheSharedPortOfThe2014ProfileAreIgnored() throws Exception {
        // the destination is the instance's own return port, as with broadcasts in a 2014 game
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        try (LoopbackReceiver robot = new LoopbackReceiver();
             java.net.DatagramSocket probe = new java.net.DatagramSocket(ANY_LOOPBACK_PORT)) {
            int port = probe.getLocalPort();
            probe.close();
            InetSocketAddress shared = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
            try (EmbeddedGameController gc = new EmbeddedGameController(game, new GcConfig(GcProfile.V8, true,
                    List.of(shared), ANY_LOOPBACK_PORT, shared, null, 100, false), envelopes::add, null,
                    new touchline.app.SystemClock())) {
                gc.addEventListener(events::add);
                gc.start();
                robot.send(new ReturnPacket.V2(13, 1, ReturnPacket.ALIVE).encode(), shared);
                Await.until(() -> gc.liveness().status(13, 1, gc.runtime().now()) == RobotLiveness.Status.ONLINE, 2000,
                        "return on 3838-style shared port");
                Await.until(() -> gc.sender().packetsSent() >= 6, 3000, "own packets sent to the shared port");
                assertTrue(gc.rivals().active(gc.runtime().now()).isEmpty(), "own packets taken for a rival");
                assertEquals(0, gc.badPackets().total());
                assertTrue(events.stream().noneMatch(e -> e.contains("ANOTHER")));
            }
        }
    }

    @Test
    void matchModeFollowsTheStateWeSend() throws Exception {
        MatchMode matchMode = new MatchMode(new touchline.app.SystemClock());
        try (LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = start(GcProfile.HL12, robot.address(), false, matchMode)) {
            Await.until(() -> gc.sender().packetsSent() >= 1, 2000, "first packet");
            assertTrue(matchMode.mayConsoleSend());
            gc.runtime().perform(new ToReady()).join();
            gc.runtime().perform(new ToSet()).join();
            gc.runtime().perform(new ToPlaying()).join();
            Await.until(() -> !matchMode.mayConsoleSend(), 2000, "console silenced");
            assertTrue(matchMode.hold("debug option request"));
        }
    }

    @Test
    void periodicSendGoesOutWithItsOwnTimeWhileTheOwnerIsHeld() throws Exception {
        ManualClock clock = new ManualClock(1_000_000);
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock);
        try (LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = new EmbeddedGameController(game, new GcConfig(GcProfile.HL12, false,
                     List.of(robot.address()), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT, null, 50, false),
                     envelopes::add, null, new touchline.app.SystemClock())) {
            gc.start();
            gc.runtime().perform(new ToReady()).join();
            gc.runtime().perform(new ToSet()).join();
            try (HeldOwner held = new HeldOwner(gc.runtime())) {
                // the owner publishes PLAYING, then its listener holds it: no event runs from now on
                gc.runtime().perform(new ToPlaying());
                assertTrue(held.awaitHeld(), "the game's owner is held");
                int atHold = gc.runtime().snapshot().robots().secsRemaining();
                clock.advance(5_000);
                // the sender's grid goes on with the game's time run on to each send, not the held owner's last state
                Await.until(() -> envelopes.stream().anyMatch(e -> e.direction() == Direction.OUT
                                && new HlGameState12().decode(e.raw()).value().secsRemaining() == atHold - 5),
                        10_000, "a periodic datagram 5 s on while the owner is held");
                assertTrue(held.holding(), "the owner was held all along");
            }
        }
    }
}
