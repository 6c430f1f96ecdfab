package touchline.transport.gamecontroller;

import touchline.app.game.EmbeddedGameController;
import touchline.app.game.GameStateWatch;

import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.app.game.MatchMode;
import touchline.transport.Envelope;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A 2026 field on loopback: the official HSL GameController's datagrams (golden files) drive
 * match mode and the rival warning through the same recognition as the older formats, and
 * bad datagrams are counted with their reason while the next good one is used.
 */
class HslFieldListeningTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private final List<Envelope> envelopes = new CopyOnWriteArrayList<>();
    private final MatchMode matchMode = new MatchMode(new touchline.app.SystemClock());

    static byte[] golden(String file) throws IOException {
        try (InputStream in = HslFieldListeningTest.class.getResourceAsStream("/golden/gamecontroller/hsl20/" + file)) {
            return in.readAllBytes();
        }
    }

    private static byte[] with(byte[] bytes, int offset, int value) {
        byte[] out = bytes.clone();
        out[offset] = (byte) value;
        return out;
    }

    @Test
    void theOfficialVersion20PlayingSilencesTheConsole() throws Exception {
        try (GameStateWatch watch = new GameStateWatch(ANY_LOOPBACK_PORT, envelopes::add, matchMode, new touchline.app.SystemClock(),
                new touchline.app.SystemClock()).start();
             LoopbackReceiver gc = new LoopbackReceiver()) {
            gc.send(golden("00-initial.bin"), watch.localAddress());
            Await.until(() -> envelopes.size() == 1, 2000, "INITIAL heard");
            assertEquals("gc.hsl20", envelopes.get(0).kind());
            assertNull(envelopes.get(0).error());
            assertTrue(matchMode.mayConsoleSend());
            gc.send(golden("07-playing-after-delay.bin"), watch.localAddress());
            Await.until(() -> !matchMode.mayConsoleSend(), 2000, "console silenced by v20 PLAYING");
            assertTrue(matchMode.notice().contains("PLAYING"), matchMode.notice());
        }
    }

    @Test
    void badDatagramsAreCountedWithTheirReasonAndNeverBelieved() throws Exception {
        byte[] playing = golden("07-playing-after-delay.bin");
        byte[] splAsV20 = with(Arrays.copyOf(playing, 118), 4, 20);
        List<byte[]> bad = List.of(Arrays.copyOf(playing, 157), with(playing, 4, 21), splAsV20,
                golden("05-playing-delayed.monitor.bin"), with(playing, 10, 5));
        List<String> reasons = List.of("expected 158 bytes, got 157", "version byte 21", "got 118",
                "did not register as its monitor", "state 5 not in 0..4");
        try (GameStateWatch watch = new GameStateWatch(ANY_LOOPBACK_PORT, envelopes::add, matchMode, new touchline.app.SystemClock(),
                new touchline.app.SystemClock()).start();
             LoopbackReceiver gc = new LoopbackReceiver()) {
            gc.send(golden("00-initial.bin"), watch.localAddress());
            for (byte[] b : bad) {
                gc.send(b, watch.localAddress());
            }
            Await.until(() -> watch.badPackets().total() == bad.size(), 2000, "every bad datagram counted");
            assertTrue(matchMode.mayConsoleSend(), "no bad datagram (not even the PLAYING ones) changed match mode");
            for (int i = 0; i < reasons.size(); i++) {
                String error = envelopes.get(i + 1).error();
                assertTrue(error != null && error.contains(reasons.get(i)), error + " should say " + reasons.get(i));
            }
            String source = "127.0.0.1:" + gc.address().getPort();
            assertEquals(bad.size(), watch.badPackets().bySource().get(source).count());
            gc.send(playing, watch.localAddress());
            Await.until(() -> !matchMode.mayConsoleSend(), 2000, "the next good datagram is used");
        }
    }

    @Test
    void trueDataFromTheGameControllerWeRegisteredWithIsBelieved() throws Exception {
        MonitorRegistrations registrations = new MonitorRegistrations();
        registrations.requested(InetAddress.getLoopbackAddress());
        try (GameStateWatch watch = new GameStateWatch(ANY_LOOPBACK_PORT, envelopes::add, matchMode, registrations,
                new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
             LoopbackReceiver gc = new LoopbackReceiver()) {
            // during the 10 s after the whistle robots see SET, the monitor copy says PLAYING
            gc.send(golden("05-playing-delayed.monitor.bin"), watch.localAddress());
            Await.until(() -> !matchMode.mayConsoleSend(), 2000, "true PLAYING believed");
            assertEquals("gc.hsl20.truedata", envelopes.get(0).kind());
            assertEquals(0, watch.badPackets().total());
        }
    }

    @Test
    void anOfficialVersion20GameControllerIsARivalOfOurs() throws Exception {
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        try (LoopbackReceiver robot = new LoopbackReceiver();
             LoopbackReceiver official = new LoopbackReceiver();
             EmbeddedGameController gc = new EmbeddedGameController(game, new GcConfig(GcProfile.HL12, false,
                     List.of(robot.address()), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT, 500, false),
                     envelopes::add, matchMode, new touchline.app.SystemClock())) {
            gc.start();
            official.send(golden("07-playing-after-delay.bin"), gc.rivalAddress());
            Await.until(() -> !gc.rivals().active(gc.runtime().now()).isEmpty(), 2000, "rival heard");
            var rival = gc.rivals().active(gc.runtime().now()).get("127.0.0.1:" + official.address().getPort());
            assertEquals("gc.hsl20", rival.kind());
            assertEquals("5 vs 14", rival.teams());
            assertTrue(gc.rivalWarning().contains("gc.hsl20 PLAYING 5 vs 14"), gc.rivalWarning());
            Await.until(() -> !matchMode.mayConsoleSend(), 2000, "the rival's PLAYING counts for match mode");
            official.send(with(golden("07-playing-after-delay.bin"), 4, 21), gc.rivalAddress());
            Await.until(() -> gc.badPackets().total() == 1, 2000, "a bad rival datagram counted");
            assertTrue(gc.badPackets().bySource().values().iterator().next().lastReason().contains("version byte 21"));
        }
    }
}
