package touchline.ui;

import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.game.EmbeddedGameController;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.ToReady;
import touchline.testing.Await;
import touchline.testing.HeldOwner;
import touchline.transport.UdpConfig;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The application's stop, which JavaFX calls on its own thread: it only starts the console's
 * close, which ends later on its own thread.
 */
class TouchlineAppTest {

    @Test
    void stopReturnsWhileTheConsolesCloseIsHeld() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)).withGameControllerPort(0);
        Console console = new Console(config).start();
        boolean stopped = false;
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            // a running GameController with its game's thread held: the console's close (which
            // stops it and joins that thread) cannot end
            GcConfig gc = new GcConfig(GcProfile.HL12, false,
                    List.of(new InetSocketAddress("127.0.0.1", robot.getLocalPort())), null,
                    new InetSocketAddress("127.0.0.1", 0), null, GcConfig.INTERVAL_MS, false);
            EmbeddedGameController running = console.referee().start(
                    new Game(LeagueParams.hlSimulationKidSize(), 3, 1, 4, 0, console.referee().gameClock()), gc);
            try (HeldOwner owner = new HeldOwner(running.runtime())) {
                running.runtime().perform(new ToReady()); // a change: the listener holds gc-game
                assertTrue(owner.awaitHeld(), "the game's thread is held");
                new TouchlineApp(console).stop();
                stopped = true;
                assertTrue(console.referee().gameController().isPresent(),
                        "stop returned while the close (stopping the GameController) was held");
            }
            Await.until("the console closed", () -> console.referee().gameController().isEmpty()
                    && Thread.getAllStackTraces().keySet().stream().noneMatch(t -> t.getName().equals("touchline-close")));
        } finally {
            if (!stopped) {
                console.close();
            }
        }
    }
}
