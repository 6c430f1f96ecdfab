package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.ConnectionState;
import touchline.transport.nao.NaoCall;
import touchline.transport.nao.NaoLinkConfig;
import touchline.transport.nao.SequenceOutcome;
import touchline.transport.nao.WalkInput;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A NAO behind the application core on a field: the official HSL GameController's v20 PLAYING
 * datagram (golden file) reaches the console's GameController port, and from then on every
 * call and move of the console's {@link NaoSession} is held back with the reason and the
 * {@code touchline-nao-sim} (on loopback) gets nothing; after the FINISHED datagram and the
 * play memory, the same moves go through, and their requests are on the console's stream.
 */
@Tag("integration")
class NaoSessionMatchModeIntegrationTest {

    private static <T> T get(CompletableFuture<T> f) throws Exception {
        return f.get(30, TimeUnit.SECONDS);
    }

    @Test
    void duringPlayEveryNaoCallIsHeldAndNothingReachesTheRobotAfterPlayItGoesThrough() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-nao-sim");
        List<Envelope> naoOut = new CopyOnWriteArrayList<>();
        int gcPort = HslMatchModeIntegrationTest.freeLoopbackPort();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withGameControllerPort(gcPort);
        try (RobotProcess sim = RobotProcess.of(List.of(RobotProcess.binDir().resolve("touchline-nao-sim").toString(),
                "--bind", "127.0.0.1", "--rpc-port", "0", "--cam-port", "0")).start();
             Console console = new Console(config).start();
             DatagramSocket gc = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.OUT && e.channel() == Channel.NAO_RPC) {
                    naoOut.add(e);
                }
            });
            NaoSession nao = console.naos().connect("127.0.0.1", sim.port(), 0, null, NaoLinkConfig.defaults());
            assertEquals(List.of(nao), console.naos().sessions());
            Await.until("the NAO online", () -> nao.state() == ConnectionState.ONLINE);
            Await.until("the console heard no GameController at its start", () -> console.referee().matchMode().mayConsoleSend());

            byte[] playing = HslMatchModeIntegrationTest.golden("07-playing-after-delay.bin");
            gc.send(new DatagramPacket(playing, playing.length, InetAddress.getLoopbackAddress(), gcPort));
            Await.until("match mode from the v20 datagram", () -> console.referee().matchMode().playIsOn());

            CallOutcome insert = get(nao.call(NaoCall.of("ALMemory", "insertData", "Touchline/held", 1)));
            assertInstanceOf(CallOutcome.HeldBack.class, insert);
            assertTrue(insert.describe().startsWith("held back: match mode, game is PLAYING"), insert.describe());
            assertTrue(insert.describe().endsWith("; not sent"), insert.describe());
            SequenceOutcome stand = get(nao.stand());
            assertEquals(0, stand.failedIndex(), stand.describe());
            assertInstanceOf(CallOutcome.HeldBack.class, stand.outcomes().get(0));
            assertInstanceOf(CallOutcome.HeldBack.class, get(nao.walk(new WalkInput(1, 0, 0))));
            assertEquals(List.of(), naoOut, "nothing left the console for the NAO during play");
            assertEquals(0, nao.stats().sent());

            byte[] finished = HslMatchModeIntegrationTest.golden("53-finished.bin");
            gc.send(new DatagramPacket(finished, finished.length, InetAddress.getLoopbackAddress(), gcPort));
            Await.until("play over (FINISHED and the play memory)", () -> console.referee().matchMode().mayConsoleSend());

            assertInstanceOf(CallOutcome.Failed.class, get(nao.call(NaoCall.of("ALMemory", "getData", "Touchline/held"))),
                    "the held insertData never ran on the robot");
            SequenceOutcome standAfter = get(nao.stand());
            assertTrue(standAfter.ok(), standAfter.describe());
            assertEquals(new CallOutcome.Value("Standing"), get(nao.call(NaoCall.of("ALRobotPosture", "getPostureFamily"))));
            assertTrue(naoOut.stream().anyMatch(e -> e.kind().equals("ALRobotPosture.goToPosture")),
                    "the move's request is on the console's stream (recorder, views)");

            nao.close();
            assertEquals(List.of(), console.naos().sessions());
        }
    }
}
