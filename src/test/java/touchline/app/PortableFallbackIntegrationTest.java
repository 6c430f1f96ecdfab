package touchline.app;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.game.ToReady;
import touchline.model.RobotSnapshot;
import touchline.proto.Fumanoid;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.testing.Await;
import touchline.testing.Requirement;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpBackend;
import touchline.transport.UdpConfig;
import touchline.transport.gamecontroller.GcSender;
import touchline.transport.gamecontroller.RealtimePriority;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The console on macOS and Windows, tested on Linux by forcing every portable fallback: the NIO
 * UDP transport instead of epoll/recvmmsg, and normal priority for the GameController's sender
 * ({@code -Dtouchline.realtime=off}). A real simulated robot is decoded, a debug option is
 * switched on and streams, the GameController sends on its cadence, and the window's report
 * (Help → About, status bar) says which fallbacks run. The pom's {@code portable-fallbacks}
 * execution runs the other key integration tests under the same two settings.
 */
@Tag("integration")
class PortableFallbackIntegrationTest {

    private final List<Envelope> seen = new CopyOnWriteArrayList<>();
    private String realtimeBefore;

    @BeforeEach
    void forceNormalPriority() {
        Requirement.robotSide("touchline-robot");
        realtimeBefore = System.setProperty(RealtimePriority.PROPERTY, "off");
    }

    @AfterEach
    void restore() {
        if (realtimeBefore == null) {
            System.clearProperty(RealtimePriority.PROPERTY);
        } else {
            System.setProperty(RealtimePriority.PROPERTY, realtimeBefore);
        }
    }

    @Test
    void onNioARobotIsDecodedAndAnOptionSwitchedOnStreams() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1")
                .withListenPort(0).withTransport("nio"));
        try (Console console = new Console(config).start()) {
            assertEquals(UdpBackend.Kind.NIO, console.field().udp().backend().kind());
            RuntimeReport report = console.field().runtime();
            assertEquals("NIO · normal priority", report.portability(), "the status bar says both fallbacks");
            assertTrue(report.lines().stream().anyMatch(l -> l.equals("UDP transport: NIO (asked for)")
                    || l.startsWith("UDP transport: NIO (asked for); ")), report.lines().toString());
            assertTrue(report.lines().contains("GameController sender: normal priority (switched off "
                    + "(-Dtouchline.realtime=off))"), report.lines().toString());

            console.field().bus().subscribe(seen::add);
            try (RobotProcess r = RobotProcess.robot(9, console.field().port()).start()) {
                Await.until("robot 9 appears over NIO", () -> console.field().robots().robot(9).map(RobotSnapshot::online).orElse(false));
                assertEquals(13, console.field().robots().robot(9).orElseThrow().teamId());
                Await.until("option list", () -> console.field().options().options(9).listReceived());
                assertTrue(console.optionSwitches().set(9, "demo.text", true).isSent(), "the request went out over NIO");
                Await.until("demo.text streams", () -> seen.stream().anyMatch(e -> e.direction() == Direction.IN
                        && e.robotId() == 9 && e.message() instanceof Fumanoid.Message m
                        && m.hasExtension(Fumanoid.debugText)
                        && m.getExtension(Fumanoid.debugText).getOption().equals("demo.text")));
            }
        }
    }

    @Test
    void theGameControllerSendsAtNormalPriorityWhenRealTimeIsNotAvailable() throws Exception {
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        HlGameState12 format = new HlGameState12();
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
             GcSender sender = new GcSender(p -> game.controlData(), List.of(format),
                     List.of((InetSocketAddress) robot.getLocalSocketAddress()), null, e -> { }, 100,
                     new touchline.app.SystemClock())) {
            sender.useRealtimePriority(true); // asked for, as the tab and `gc` do by default
            game.addListener(sender::sendNow);
            sender.start();
            assertEquals("switched off (-Dtouchline.realtime=off)", sender.awaitRealtimeOutcome(5000));
            robot.setSoTimeout(3000);
            byte[] buf = new byte[2048];
            DatagramPacket first = new DatagramPacket(buf, buf.length);
            robot.receive(first);
            assertEquals(GameControlData.STATE_INITIAL,
                    format.decode(java.util.Arrays.copyOf(buf, first.getLength())).value().state());
            game.perform(new ToReady());
            // the change goes out at once; at most a periodic INITIAL packet may come before it
            int state = GameControlData.STATE_INITIAL;
            for (int i = 0; i < 5 && state != GameControlData.STATE_READY; i++) {
                DatagramPacket p = new DatagramPacket(buf, buf.length);
                robot.receive(p); // SocketTimeoutException after 3 s fails the test
                state = format.decode(java.util.Arrays.copyOf(buf, p.getLength())).value().state();
            }
            assertEquals(GameControlData.STATE_READY, state, "READY reached the robot at normal priority");
        }
    }
}
