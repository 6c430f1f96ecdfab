package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.model.RobotSnapshot;
import touchline.proto.Fumanoid;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.SendResult;
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
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * GameController spoofing against the robot itself (the real firmware binary, on loopback): the
 * GameController says PLAYING to the robot every 500 ms, a forger on another port floods it with
 * FINISHED. The robot follows the GameController it heard first, so it keeps the game's debug
 * limit (no option data, the Status once a second, game state PLAYING) and counts the forger's
 * packets in its Status ({@code gcOtherSource}).
 */
@Tag("integration")
class RobotGameControllerSpoofingIntegrationTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);
    private static final int FORGED = 1000;

    private static Fumanoid.Status status(Envelope e) {
        return e.direction() == Direction.IN && e.robotId() == 8 ? e.extension(Fumanoid.status) : null;
    }

    @Test
    void aFloodOfForgedFinishedFromAnotherSourceDoesNotLiftTheRobotsDebugLimit() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        byte[] playing = HslMatchModeIntegrationTest.golden("07-playing-after-delay.bin");
        byte[] finished = playing.clone();
        finished[10] = 4; // state FINISHED, the same game otherwise
        List<Envelope> fromRobot = new CopyOnWriteArrayList<>();
        AtomicBoolean recording = new AtomicBoolean();
        AtomicInteger dataBeforeGame = new AtomicInteger();
        AtomicInteger forgedSent = new AtomicInteger();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withGameControllerPort(HslMatchModeIntegrationTest.freeLoopbackPort());
        ScheduledExecutorService field = Executors.newScheduledThreadPool(2);
        try (Console console = new Console(config).start();
             RobotProcess robot = RobotProcess.robot(8, console.field().port()).start();
             DatagramSocket gc = new DatagramSocket(ANY_LOOPBACK_PORT);
             DatagramSocket forger = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            InetSocketAddress robotAddress = new InetSocketAddress(InetAddress.getLoopbackAddress(), robot.port());
            console.field().bus().subscribe(e -> {
                if (e.direction() != Direction.IN || e.robotId() != 8) {
                    return;
                }
                if (recording.get()) {
                    fromRobot.add(e);
                } else if (e.kind().equals("debugText")) {
                    dataBeforeGame.incrementAndGet();
                }
            });
            Await.until("option list", 5000, () -> console.field().options().options(8).listReceived());
            assertEquals(SendResult.Outcome.SENT, console.optionSwitches().set(8, "demo.text", true).outcome());
            Await.until("demo.text data flowing", 5000, () -> dataBeforeGame.get() > 0);

            // the GameController's own rate: a packet every 500 ms
            field.scheduleAtFixedRate(() -> send(gc, playing, robotAddress), 0, 500, TimeUnit.MILLISECONDS);
            Await.until("the robot in PLAYING", 5000, () -> "PLAYING".equals(console.field().robots().robot(8).map(RobotSnapshot::gameState).orElse("")));
            recording.set(true);
            field.scheduleAtFixedRate(() -> {
                if (forgedSent.get() < FORGED) {
                    send(forger, finished, robotAddress);
                    forgedSent.incrementAndGet();
                }
            }, 0, 2, TimeUnit.MILLISECONDS);
            Await.until("the forger's flood sent", 10_000, () -> forgedSent.get() >= FORGED);
            int seen = fromRobot.size();
            Await.until("a Status after the flood", 5000, () -> fromRobot.subList(seen, fromRobot.size()).stream()
                    .anyMatch(e -> status(e) != null));

            List<String> kinds = fromRobot.stream().map(Envelope::kind).distinct().toList();
            assertEquals(List.of("status"), kinds, "in play the robot sends its Status and nothing else");
            List<Fumanoid.Status> statuses = fromRobot.stream().map(RobotGameControllerSpoofingIntegrationTest::status)
                    .filter(s -> s != null).toList();
            assertTrue(statuses.stream().allMatch(s -> s.getGameState().equals("PLAYING")),
                    "the robot believed a forged state: " + statuses.stream().map(Fumanoid.Status::getGameState).toList());
            Fumanoid.Status last = statuses.get(statuses.size() - 1);
            assertTrue(last.hasGcOtherSource() && last.getGcOtherSource() > 0, "the forger's packets counted: " + last);
            String shown = console.field().robots().robot(8).orElseThrow().gameStateShown();
            assertTrue(shown.startsWith("PLAYING (") && shown.endsWith(" from another GameController, not believed)"),
                    shown);
            assertTrue(robot.isAlive());
        } finally {
            field.shutdownNow();
        }
    }

    private static void send(DatagramSocket from, byte[] d, InetSocketAddress to) {
        try {
            from.send(new DatagramPacket(d, d.length, to));
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
