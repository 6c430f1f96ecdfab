package touchline.transport.gamecontroller;

import touchline.app.game.GameStateWatch;

import org.junit.jupiter.api.Test;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.app.game.MatchMode;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.protocol.gamecontroller.SplGameState18;
import touchline.transport.Envelope;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** An official GameController's packets silence the console while play is on. */
class GameStateWatchTest {

    @Test
    void officialGameControllerPlayingBlocksTheConsole() throws Exception {
        MatchMode matchMode = new MatchMode(new touchline.app.SystemClock());
        List<Envelope> envelopes = new CopyOnWriteArrayList<>();
        Game official = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        SplGameState18 format = new SplGameState18();
        try (GameStateWatch watch = new GameStateWatch(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0),
                envelopes::add, matchMode, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
             LoopbackReceiver gc = new LoopbackReceiver()) {
            gc.send(format.encode(official.controlData()), watch.localAddress());
            gc.send(new byte[]{'R', 'G', 'm', 'e', 99}, watch.localAddress());
            Await.until(() -> envelopes.size() == 2, 2000, "two envelopes");
            assertTrue(matchMode.mayConsoleSend(), "INITIAL lets the console send");
            assertEquals("gc.spl18", envelopes.get(0).kind());
            assertEquals("gc.unknown", envelopes.get(1).kind());
            assertTrue(envelopes.get(1).isMalformed());
            official.perform(new ToReady());
            official.perform(new ToSet());
            official.perform(new ToPlaying());
            gc.send(format.encode(official.controlData()), watch.localAddress());
            Await.until(() -> !matchMode.mayConsoleSend(), 2000, "console silenced");
            assertTrue(matchMode.hold("debug option request"));
            assertTrue(matchMode.notice().contains("PLAYING"), matchMode.notice());
        }
    }
}
