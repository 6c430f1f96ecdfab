package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.game.MatchMode;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A console started in the middle of a game on Wi-Fi that loses every second GameController
 * packet (real UDP on loopback, the losses made on purpose): the GameController says PLAYING every
 * 500 ms, the console hears it once a second, the first time 1 s after it started. Its robot (the real firmware, which hears no GameController and reports INITIAL) is there
 * from the first moment, so the console would ask it for its option list as soon as it may talk:
 * it must not, before or after the PLAYING it hears 1 s after its start.
 */
@Tag("integration")
class LossyGameControllerStartIntegrationTest {

    @Test
    void aConsoleStartedDuringPlayHearsAGameControllerLosingOnePacketInTwoBeforeItTalks() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        byte[] playing = HslMatchModeIntegrationTest.golden("07-playing-after-delay.bin");
        int consolePort = HslMatchModeIntegrationTest.freeLoopbackPort();
        int gcPort = HslMatchModeIntegrationTest.freeLoopbackPort();
        InetSocketAddress consoleGcPort = new InetSocketAddress(InetAddress.getLoopbackAddress(), gcPort);
        AtomicInteger sent = new AtomicInteger();
        List<Envelope> out = new CopyOnWriteArrayList<>();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(consolePort))
                .withGameControllerPort(gcPort);
        ScheduledExecutorService field = Executors.newSingleThreadScheduledExecutor();
        try (DatagramSocket gc = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
             RobotProcess robot = RobotProcess.robot(8, consolePort).start();
             Console console = new Console(config)) {
            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.OUT) {
                    out.add(e);
                }
            });
            console.start();
            // the GameController's packets from here on, every 500 ms: the 1st, 3rd, 5th... are lost,
            // so the first the console hears comes 1 s after it started listening
            field.scheduleAtFixedRate(() -> {
                if (sent.incrementAndGet() % 2 == 1) {
                    return;
                }
                try {
                    gc.send(new DatagramPacket(playing, playing.length, consoleGcPort));
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }, MatchMode.GAMECONTROLLER_INTERVAL_MS, MatchMode.GAMECONTROLLER_INTERVAL_MS, TimeUnit.MILLISECONDS);

            // watched from the start to the PLAYING heard: the console never may talk in between
            AtomicBoolean mayTalk = new AtomicBoolean();
            Await.until("PLAYING heard", 5000, () -> {
                if (console.referee().matchMode().mayConsoleSend()) {
                    mayTalk.set(true);
                }
                return console.referee().matchMode().playIsOn();
            });
            assertFalse(mayTalk.get(), "the console could talk to robots before it heard the lossy GameController");
            Await.until("the robot seen", 5000, () -> console.field().robots().robot(8).isPresent());
            long before = console.referee().matchMode().heldCount();
            Await.until("the option list request held back", 5000, () -> console.referee().matchMode().heldCount() > before);
            assertEquals(List.of(), out, "nothing to the robot");
            assertTrue(console.referee().matchMode().notice().contains("PLAYING"), console.referee().matchMode().notice());
        } finally {
            field.shutdownNow();
        }
    }
}
