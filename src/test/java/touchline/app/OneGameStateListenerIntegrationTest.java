package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.RivalGameControllers;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.testing.Await;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A console that referees hears the game-state port through its one listener: a rival's packet
 * is one envelope, one entry in the one table of other GameControllers (the console's intruders
 * are the referee's rivals), and heard by match mode; its own packets heard back are not taken
 * for the field's GameController.
 */
@Tag("integration")
class OneGameStateListenerIntegrationTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private static int freeLoopbackPort() throws Exception {
        try (DatagramSocket probe = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            return probe.getLocalPort();
        }
    }

    @Test
    void aRefereeingConsoleHearsItsRivalsThroughItsOneListener() throws Exception {
        int gcPort = freeLoopbackPort();
        InetSocketAddress gameStatePort = new InetSocketAddress(InetAddress.getLoopbackAddress(), gcPort);
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withGameControllerPort(gcPort);
        List<Envelope> heard = new CopyOnWriteArrayList<>();
        try (Console console = new Console(config).start();
             DatagramSocket rival = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.IN && e.channel() == Channel.GAMECONTROLLER) {
                    heard.add(e);
                }
            });
            // our GameController sends to the very port the console listens on, as a broadcast would
            EmbeddedGameController gc = console.referee().start(
                    new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, console.referee().gameClock()),
                    new GcConfig(GcProfile.HL12, false, List.of(gameStatePort), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT,
                            gameStatePort, 50, false));
            assertEquals(gameStatePort.getPort(), gc.rivalAddress().getPort(), "rivals heard on the console's port");
            assertSame(console.referee().sources().others(), gc.rivals(), "one table of other GameControllers");
            Await.until("own packets sent", () -> gc.packetsSent() >= 5);

            Game other = new Game(LeagueParams.hlSimulationKidSize(), 3, 1, 4, 0, console.referee().gameClock());
            other.perform(new ToReady());
            other.perform(new ToSet());
            other.perform(new ToPlaying());
            byte[] playing = new HlGameState12().encode(other.controlData());
            rival.send(new DatagramPacket(playing, playing.length, gameStatePort));
            String key = "127.0.0.1:" + rival.getLocalPort();
            Await.until("the rival counted", () -> gc.rivals().active(console.referee().gameClock().millis()).containsKey(key));
            assertTrue(gc.rivalWarning().contains(key), gc.rivalWarning());
            assertTrue(console.referee().sources().activeIntruders().stream().anyMatch(i -> i.source().equals(key)),
                    "the console's intruders are the referee's rivals");
            Await.until("match mode hears the rival's PLAYING", () -> console.referee().matchMode().playIsOn());
            Await.until("the rival's envelope", () -> heard.stream().anyMatch(e -> e.peer().getPort() == rival.getLocalPort()));
            assertEquals(1, heard.stream().filter(e -> e.peer().getPort() == rival.getLocalPort()).count(),
                    "one envelope per datagram: one listener");
            assertTrue(heard.stream().allMatch(e -> e.peer().getPort() == rival.getLocalPort()),
                    "our own packets heard back are no GameController of the field");
            assertEquals("", console.referee().sources().pinnedHost(), "our own GameController is not pinned as the field's");
            console.referee().stop();
        }
    }

    @Test
    void aRivalWarnsAsLongAsItsClaimActsOnMatchMode() {
        RivalGameControllers rivals = new RivalGameControllers();
        rivals.heard(new InetSocketAddress("127.0.0.1", 3838), "gc.hl12", null, 0);
        assertFalse(rivals.warning(touchline.app.game.MatchMode.STALE_MS).isEmpty(),
                "a rival heard within match mode's window still warns");
        assertTrue(rivals.warning(touchline.app.game.MatchMode.STALE_MS + 1).isEmpty());
    }
}
