package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.app.game.GameControllerSources;
import touchline.game.LeagueParams;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.SendResult;
import touchline.transport.UdpConfig;
import touchline.app.game.EmbeddedGameController;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * GameController spoofing end to end on loopback: a real GameController (the project's sender)
 * plays PLAYING to the console's GameController port from 127.0.0.1; a forger on 127.0.0.2 sends
 * FINISHED to the same port, and so does a second socket on 127.0.0.1 (a forger using the
 * GameController's own address). The console stays in match mode, shows the other source as a
 * warning with its address and count, flags the packet numbers going back, and still holds a
 * debug-option request for its robot.
 */
@Tag("integration")
class GameControllerSpoofingIntegrationTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private static int freeLoopbackPort() throws Exception {
        try (DatagramSocket probe = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            return probe.getLocalPort();
        }
    }

    private static byte[] forgedFinished(int packetNumber) throws Exception {
        try (var in = GameControllerSpoofingIntegrationTest.class.getResourceAsStream(
                "/golden/gamecontroller/hl12/04-playing.bin")) {
            HlGameState12 format = new HlGameState12();
            GameControlData d = format.decode(in.readAllBytes()).value();
            return format.encode(new GameControlData(packetNumber, d.playersPerTeam(), d.gameType(),
                    d.competitionType(), GameControlData.STATE_FINISHED, d.firstHalf(), d.kickOffTeam(),
                    d.secondaryState(), d.setPlayTeam(), d.setPlayMode(), d.dropInTeam(), d.dropInTime(), 0,
                    d.secondaryTime(), d.teams(), d.gamePhase(), d.stopped()));
        }
    }

    @Test
    void aSecondSourceSendingFinishedDuringPlayingIsFlaggedAndDoesNotEndMatchMode() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        List<Envelope> out = new CopyOnWriteArrayList<>();
        List<Envelope> gcHeard = new CopyOnWriteArrayList<>();
        int gcPort = freeLoopbackPort();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withGameControllerPort(gcPort);
        InetSocketAddress consoleGcPort = new InetSocketAddress(InetAddress.getLoopbackAddress(), gcPort);
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        try (Console console = new Console(config).start();
             RobotProcess robot = RobotProcess.robot(8, console.field().port()).start();
             EmbeddedGameController referee = new EmbeddedGameController(game, new GcConfig(GcProfile.HL12, false,
                     List.of(consoleGcPort), ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT, null, 500, false), e -> { }, null, new touchline.app.SystemClock());
             DatagramSocket forger = new DatagramSocket(new InetSocketAddress("127.0.0.2", 0));
             DatagramSocket sameAddressForger = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.OUT) {
                    out.add(e);
                } else if (e.channel() == Channel.GAMECONTROLLER) {
                    gcHeard.add(e);
                }
            });
            Await.until("option list", () -> console.field().options().options(8).listReceived());
            referee.runtime().perform(new ToReady()); // enqueued: the owner applies them once started
            referee.runtime().perform(new ToSet());
            referee.runtime().perform(new ToPlaying());
            referee.start();
            Await.until("match mode from the GameController's PLAYING", () -> console.referee().matchMode().playIsOn());
            assertEquals("127.0.0.1", console.referee().sources().pinnedHost());

            int forged = 10;
            for (int i = 0; i < forged; i++) {
                byte[] finished = forgedFinished(i);
                forger.send(new DatagramPacket(finished, finished.length, consoleGcPort));
            }
            Await.until("the forger's packets counted", () -> console.referee().sources().activeIntruders().stream()
                    .anyMatch(in -> in.packets() == forged));
            byte[] finished = forgedFinished(200);
            sameAddressForger.send(new DatagramPacket(finished, finished.length, consoleGcPort));
            Await.until("the packet number going back flagged", () -> console.referee().sources().suspicious() > 0);

            assertTrue(console.referee().matchMode().playIsOn(), "a forged FINISHED never ends match mode");
            GameControllerSources.Intruder intruder = console.referee().sources().activeIntruders().get(0);
            assertTrue(intruder.source().startsWith("127.0.0.2:"), intruder.source());
            String status = new touchline.ui.frame.ConsoleStatus(console.field(), console.referee(), console.replays(), console.remote()).silence();
            assertTrue(status.contains("another source is sending game states: " + intruder.source() + " ("
                    + forged + " packets, last FINISHED)"), status);
            assertTrue(status.contains("Silent: match mode"), status);
            assertTrue(gcHeard.stream().filter(e -> e.peer().getAddress().getHostAddress().equals("127.0.0.2"))
                    .allMatch(e -> e.error() != null && e.error().contains("not believed")));

            out.clear();
            SendResult held = console.optionSwitches().set(8, "demo.text", true);
            assertEquals(SendResult.Outcome.HELD, held.outcome());
            long before = console.referee().matchMode().heldCount();
            for (int i = 0; i < 3; i++) { // FINISHED keeps coming while the option session retries
                byte[] more = forgedFinished(forged + i);
                forger.send(new DatagramPacket(more, more.length, consoleGcPort));
            }
            Await.until("a retry held back", () -> console.referee().matchMode().heldCount() > before);
            assertTrue(console.referee().matchMode().playIsOn());
            assertEquals(List.of(), out, "nothing leaves the console for a robot during play");
        }
    }
}
