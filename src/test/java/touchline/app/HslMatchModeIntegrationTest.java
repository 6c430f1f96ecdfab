package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.SendResult;
import touchline.transport.UdpConfig;

import java.io.InputStream;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A console on a 2026 field: the official HSL GameController's v20 PLAYING datagram (golden
 * file) arrives on the console's GameController port, the console goes into match mode and
 * sends nothing to its robot, although the robot itself (firmware without v20) cannot say
 * that play is on.
 */
@Tag("integration")
class HslMatchModeIntegrationTest {

    static byte[] golden(String name) throws Exception {
        try (InputStream in = HslMatchModeIntegrationTest.class.getResourceAsStream("/golden/gamecontroller/hsl20/" + name)) {
            return in.readAllBytes();
        }
    }

    static int freeLoopbackPort() throws Exception {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            return probe.getLocalPort();
        }
    }

    @Test
    void theOfficialVersion20PlayingDatagramSilencesTheConsole() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        List<Envelope> out = new CopyOnWriteArrayList<>();
        List<Envelope> heard = new CopyOnWriteArrayList<>();
        int gcPort = freeLoopbackPort();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withGameControllerPort(gcPort);
        try (Console console = new Console(config).start();
             RobotProcess robot = RobotProcess.robot(8, console.field().port()).start();
             DatagramSocket gc = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.OUT) {
                    out.add(e);
                } else if (e.channel() == Channel.GAMECONTROLLER) {
                    heard.add(e);
                }
            });
            Await.until("option list", () -> console.field().options().options(8).listReceived());
            assertTrue(console.referee().matchMode().mayConsoleSend());

            byte[] playing = golden("07-playing-after-delay.bin");
            assertEquals(158, playing.length);
            gc.send(new DatagramPacket(playing, playing.length, InetAddress.getLoopbackAddress(), gcPort));
            Await.until("match mode from the v20 datagram", () -> console.referee().matchMode().playIsOn());
            // counted from here: until the datagram was believed the console could still ask for
            // the robot's option list (it did once, beside a loaded machine)
            out.clear();
            assertEquals("gc.hsl20", heard.get(0).kind());
            assertTrue(console.referee().matchMode().notice().contains("PLAYING"), console.referee().matchMode().notice());

            SendResult held = console.optionSwitches().set(8, "demo.text", true);
            assertEquals(SendResult.Outcome.HELD, held.outcome());
            long before = console.referee().matchMode().heldCount();
            // the option session retries on its own: wait for a retry to be held, then nothing may have left
            Await.until("a retry held back", () -> console.referee().matchMode().heldCount() > before);
            assertEquals(List.of(), out, "nothing leaves the console for a robot during play");
        }
    }

    @Test
    void asAMonitorTheConsoleBelievesTheTrueStateAndSeesTheRobotsThroughTheGameController() throws Exception {
        int gcPort = freeLoopbackPort();
        int forwardPort = freeLoopbackPort();
        try (DatagramSocket gc = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            gc.setSoTimeout(5000);
            ConsoleConfig config = ConsoleConfig.defaults()
                    .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                    .withGameControllerPort(gcPort)
                    .withGcMonitor((InetSocketAddress) gc.getLocalSocketAddress(), forwardPort);
            try (Console console = new Console(config).start()) {
                DatagramPacket request = new DatagramPacket(new byte[16], 16);
                gc.receive(request);
                assertEquals("RGTr", new String(request.getData(), 0, 4, java.nio.charset.StandardCharsets.US_ASCII));
                assertEquals(5, request.getLength());

                // during the robots' fake SET the monitor copy already says PLAYING
                byte[] trueData = golden("05-playing-delayed.monitor.bin");
                gc.send(new DatagramPacket(trueData, trueData.length, InetAddress.getLoopbackAddress(), gcPort));
                Await.until("match mode from the true data", () -> console.referee().matchMode().playIsOn());

                byte[] robot = golden("return/r01-team5-player1-upright.bin");
                byte[] forwarded = new byte[36];
                forwarded[0] = 10;
                forwarded[3] = 7;
                System.arraycopy(robot, 0, forwarded, 4, 32);
                gc.send(new DatagramPacket(forwarded, 36, InetAddress.getLoopbackAddress(), forwardPort));
                Await.until("robot 5/1 seen through the GameController", () -> !console.referee().monitor().robots().isEmpty());
                assertEquals("10.0.0.7", console.referee().monitor().robots().values().iterator().next().robotHost());
            }
        }
    }
}
