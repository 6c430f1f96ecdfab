package touchline.app;

import touchline.testing.Await;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.SendResult;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Match mode end to end: the official GameController's PLAYING packet reaches the simulated
 * robot, the robot's keep-alive reports it, and the console holds a debug request back until a
 * packet says INITIAL again; then the request goes out by itself.
 */
@Tag("integration")
class MatchModeIntegrationTest {


    private static byte[] golden(String name) throws Exception {
        try (var in = MatchModeIntegrationTest.class.getResourceAsStream("/golden/gamecontroller/hl12/" + name)) {
            return in.readAllBytes();
        }
    }

    @Test
    void aDebugRequestIsHeldDuringPlayingAndGoesOutInInitial() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        List<Envelope> out = new CopyOnWriteArrayList<>();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config).start();
             RobotProcess robot = RobotProcess.robot(8, console.field().port()).start();
             DatagramSocket gc = new DatagramSocket()) {
            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.OUT) {
                    out.add(e);
                }
            });
            Await.until("option list", () -> console.field().options().options(8).listReceived());

            byte[] playing = golden("04-playing.bin");
            gc.send(new DatagramPacket(playing, playing.length, InetAddress.getLoopbackAddress(), robot.port()));
            Await.until("the robot reports PLAYING", () -> console.field().robots().robot(8).orElseThrow().gameState().equals("PLAYING"));
            assertTrue(console.referee().matchMode().playIsOn());

            out.clear();
            SendResult held = console.optionSwitches().set(8, "demo.text", true);
            assertEquals(SendResult.Outcome.HELD, held.outcome());
            assertTrue(held.reason().contains("PLAYING"), held.reason());
            Thread.sleep(1500); // long enough for the option session to retry once: it must stay silent
            assertEquals(List.of(), out, "nothing but GameController packets leaves the console during play");
            assertTrue(console.referee().matchMode().heldCount() >= 2);

            byte[] initial = golden("00-initial.bin");
            gc.send(new DatagramPacket(initial, initial.length, InetAddress.getLoopbackAddress(), robot.port()));
            Await.until("the robot reports INITIAL", () -> console.field().robots().robot(8).orElseThrow().gameState().equals("INITIAL"));
            Await.until("the held request went out and data streams", () ->
                    console.field().options().options(8).option("demo.text").map(o -> o.streaming()).orElse(false));
            assertTrue(out.stream().anyMatch(e -> e.message() instanceof Fumanoid.Message m
                    && m.hasExtension(Fumanoid.debugOptionRequest)));
        }
    }
}
