package touchline.transport.gamecontroller;

import touchline.app.game.EmbeddedGameController;

import org.junit.jupiter.api.Test;
import touchline.game.ManualClock;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslGameGoldenTest;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.MonitorRequest;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The embedded HSL GameController answers monitors on 127.0.0.1 as the official one does: a
 * registered monitor gets the true state (PLAYING while robots still see SET) and the robots'
 * return packets behind their address; a host that sent return packets is refused.
 */
class HslMonitorServiceTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);
    private static final int TIMEOUT_MS = 30_000;

    private final List<String> events = new CopyOnWriteArrayList<>();

    private EmbeddedGameController start(HslGame game, LoopbackReceiver robotPort) throws Exception {
        GcConfig config = new GcConfig(GcProfile.HSL20, false, List.of(robotPort.address()), ANY_LOOPBACK_PORT,
                ANY_LOOPBACK_PORT, null, 50, false);
        EmbeddedGameController gc = new EmbeddedGameController(game, config, e -> { }, null, new touchline.app.SystemClock());
        gc.addEventListener(events::add);
        return gc;
    }

    private static byte[] returnPacket() throws Exception {
        return HslGameGoldenTest.golden(20, "return/r01-team5-player1-upright.bin");
    }

    @Test
    void aRegisteredMonitorGetsTheTrueStateAndForwardedReturnPackets() throws Exception {
        ManualClock clock = new ManualClock(0);
        HslGame game = HslGameGoldenTest.goldenGame(20, clock);
        try (LoopbackReceiver robots = new LoopbackReceiver();
             LoopbackReceiver monitor = new LoopbackReceiver();
             LoopbackReceiver forwarded = new LoopbackReceiver();
             LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = start(game, robots)) {
            MonitorService service = gc.serveMonitors(ANY_LOOPBACK_PORT, monitor.address().getPort(),
                    forwarded.address().getPort());
            gc.start();
            monitor.send(new MonitorRequest().encode(), service.requestAddress());
            Await.until(() -> !service.monitors().isEmpty(), TIMEOUT_MS, "monitor registered");
            for (String c : List.of("kickoff 5", "set", "play")) {
                RefereeScript.perform(gc.runtime(), c, "monitor test");
            }
            GameControlData seen = null;
            while (seen == null || seen.state() != GameControlData.STATE_PLAYING) {
                LoopbackReceiver.Received r = monitor.receive(TIMEOUT_MS);
                assertNotNull(r, "true data");
                Decoded<GameControlData> d = HslGameState20.trueData().decode(r.data());
                assertTrue(d.isOk(), d.toString());
                seen = d.value();
            }
            assertEquals(GameControlData.STATE_SET, gc.runtime().snapshot().robots().state(), "robots still see SET");

            byte[] packet = returnPacket();
            robot.send(packet, gc.returnAddress());
            LoopbackReceiver.Received f = forwarded.receive(TIMEOUT_MS);
            assertNotNull(f, "forwarded return packet");
            assertEquals(ForwardedReturnPacket.SIZE, f.data().length);
            Decoded<ForwardedReturnPacket> fr = new ForwardedReturnPacket.Decoder().decode(f.data());
            assertTrue(fr.isOk(), fr.toString());
            assertEquals("127.0.0.1", fr.value().robotHost());
            assertArrayEquals(packet, fr.value().packet().encode());
        }
    }

    @Test
    void aHostThatSentReturnPacketsIsRefusedAsMonitorAndBadRequestsAreCounted() throws Exception {
        HslGame game = HslGameGoldenTest.goldenGame(20, new ManualClock(0));
        try (LoopbackReceiver robots = new LoopbackReceiver();
             LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = start(game, robots)) {
            MonitorService service = gc.serveMonitors(ANY_LOOPBACK_PORT, 1, 1);
            gc.start();
            robot.send(returnPacket(), gc.returnAddress());
            Await.until(() -> !gc.liveness().all(game.now()).isEmpty(), TIMEOUT_MS, "robot heard");
            robot.send(new byte[]{'R', 'G', 'T', 'r', 1}, service.requestAddress());
            robot.send(new MonitorRequest().encode(), service.requestAddress());
            // the count goes up before the event is told (another thread): wait for both
            Await.until(() -> service.badRequests() == 2
                    && events.stream().anyMatch(e -> e.contains("refused: it sends return packets")), TIMEOUT_MS,
                    "both requests refused and the refusal told");
            assertTrue(service.monitors().isEmpty());
            assertTrue(events.stream().anyMatch(e -> e.contains("WRONG_VERSION")), events.toString());
        }
    }
}
