package touchline.transport.gamecontroller;

import touchline.app.game.EmbeddedGameController;

import org.junit.jupiter.api.Test;
import touchline.game.ManualClock;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslGameGoldenTest;
import touchline.game.hsl.HslGoldenScript;
import touchline.protocol.gamecontroller.HslGameState20;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The embedded GameController in an HSL format over real UDP on 127.0.0.1: it sends the
 * official golden bytes for the scripted game, and it keeps the official HSL schedule (no
 * datagram after an ordinary change, a burst of five when play gets stopped). The game runs
 * on a manual clock; the sender's own timing is measured by {@code ./touchline bench gc}.
 */
class HslSenderLoopbackTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);
    /** Longer than any wait here: a datagram that arrives is never a periodic one after the first. */
    private static final long LONG_INTERVAL_MS = 600_000;
    private static final int RECEIVE_TIMEOUT_MS = 30_000;
    private static final int PACKET_NUMBER = 5;

    private static EmbeddedGameController start(HslGame game, InetSocketAddress dest, long intervalMs)
            throws Exception {
        GcConfig config = new GcConfig(GcProfile.HSL20, false, List.of(dest), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT,
                null, intervalMs, false);
        EmbeddedGameController gc = new EmbeddedGameController(game, config, e -> { }, null, new touchline.app.SystemClock());
        gc.start();
        return gc;
    }

    private static byte[] withoutPacketNumber(byte[] b) {
        byte[] c = Arrays.copyOf(b, b.length);
        c[PACKET_NUMBER] = 0;
        return c;
    }

    @Test
    void sendsTheGoldenBytesOfEveryStepOverUdp() throws Exception {
        ManualClock clock = new ManualClock(0);
        HslGame game = HslGameGoldenTest.goldenGame(20, clock);
        try (LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = start(game, robot.address(), 20)) {
            int steps = 0;
            for (HslGoldenScript.Step step : HslGoldenScript.of(20)) {
                clock.set(step.atMs());
                gc.runtime().tick().join();
                for (String command : step.commands()) {
                    RefereeScript.perform(gc.runtime(), command, "sender at " + step.atMs() + " ms");
                }
                if (step.file() == null) {
                    continue;
                }
                clock.set(step.sentAtMs());
                byte[] expected = withoutPacketNumber(HslGameGoldenTest.golden(20, step.file()));
                // datagrams sent before the step took effect are skipped; the sender must get to it
                byte[] last = null;
                long deadline = System.nanoTime() + RECEIVE_TIMEOUT_MS * 1_000_000L;
                while (last == null || !Arrays.equals(expected, last)) {
                    assertTrue(System.nanoTime() < deadline, step.file() + " never sent; last datagram "
                            + (last == null ? "none" : HexFormat.of().formatHex(last)));
                    LoopbackReceiver.Received r = robot.receive(RECEIVE_TIMEOUT_MS);
                    assertNotNull(r, step.file() + ": nothing received");
                    assertEquals(HslGameState20.SIZE, r.data().length, "datagram size");
                    last = withoutPacketNumber(r.data());
                }
                steps++;
            }
            assertEquals(54, steps);
        }
    }

    @Test
    void onlyTheSwitchToStoppedSendsAtOnceThenFourMore() throws Exception {
        ManualClock clock = new ManualClock(0);
        HslGame game = HslGameGoldenTest.goldenGame(20, clock);
        try (LoopbackReceiver robot = new LoopbackReceiver();
             EmbeddedGameController gc = start(game, robot.address(), LONG_INTERVAL_MS)) {
            LoopbackReceiver.Received first = robot.receive(RECEIVE_TIMEOUT_MS);
            assertNotNull(first, "the first datagram goes out at start");
            assertEquals(0, first.data()[PACKET_NUMBER]);
            // the script up to the corner kick: kick-off, team messages, set, play, ... no datagram of their own
            for (HslGoldenScript.Step step : HslGoldenScript.of(20)) {
                if (step.atMs() > 60_250) {
                    break;
                }
                clock.set(step.atMs());
                for (String command : step.commands()) {
                    RefereeScript.perform(gc.runtime(), command, "at " + step.atMs() + " ms");
                }
            }
            byte[] corner = HslGameGoldenTest.golden(20, "08-corner-kick-team14-stopped.bin");
            for (int n = 1; n <= SendSchedule.BURST_DATAGRAMS; n++) {
                LoopbackReceiver.Received r = robot.receive(RECEIVE_TIMEOUT_MS);
                assertNotNull(r, "burst datagram " + n);
                assertEquals(n, r.data()[PACKET_NUMBER], "datagram " + n + " is the burst's, nothing came between");
                assertEquals(HexFormat.of().formatHex(withoutPacketNumber(corner)),
                        HexFormat.of().formatHex(withoutPacketNumber(r.data())), "burst datagram " + n);
            }
        }
    }

    @Test
    void anHlGameIsNotSentInAnHslFormat() {
        var hl = new touchline.game.Game(touchline.game.LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0,
                new ManualClock(0));
        GcConfig config = new GcConfig(GcProfile.HSL20, false, List.of(ANY_LOOPBACK_PORT), ANY_LOOPBACK_PORT,
                ANY_LOOPBACK_PORT, null, 500, false);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new EmbeddedGameController(hl, config, x -> { }, null,
                        new touchline.app.SystemClock()).close());
        assertTrue(e.getMessage().contains("--format hsl20"), e.getMessage());
    }
}
