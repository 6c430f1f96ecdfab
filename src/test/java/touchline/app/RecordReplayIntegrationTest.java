package touchline.app;

import touchline.testing.Await;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.RobotSnapshot;
import touchline.testing.RobotProcess;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Records a simulated team through the console, replays the file into a fresh console's
 * Envelope stream, and gets back the same envelopes (order, bytes, timestamps); the replayed
 * robots appear in the model as they did live.
 */
@Tag("integration")
class RecordReplayIntegrationTest {


    private static ConsoleConfig loopback() {
        return ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
    }

    @Test
    void aRecordedTeamReplaysIntoTheSameStream(@TempDir Path dir) throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        Path file = dir.resolve("match.mcap");
        List<Envelope> live = new CopyOnWriteArrayList<>();
        try (Console console = new Console(loopback()).start()) {
            console.recordings().start(file);
            console.field().bus().subscribe(live::add);
            int port = console.field().port();
            try (RobotProcess a = RobotProcess.robot(1, port).start(); RobotProcess b = RobotProcess.robot(2, port).start()) {
                Await.until("both option lists", () -> console.field().options().options(1).listReceived()
                        && console.field().options().options(2).listReceived());
                console.optionSwitches().set(1, "demo.plotter", true);
                Await.until("plots arrive", () -> live.stream().filter(e -> e.kind().equals("debugPlot")).count() >= 5);
                Await.until("a good stretch of traffic", () -> live.size() > 40);
            }
            console.recordings().stop();
        }
        assertTrue(live.size() > 40, "recorded " + live.size());

        List<Envelope> replayed = new CopyOnWriteArrayList<>();
        try (Console console = new Console(loopback())) {
            console.field().setLiveListening(false);
            console.field().replayStream().subscribe(replayed::add);
            Replay replay = console.replays().open(file);
            assertEquals(List.of(), replay.problems());
            replay.setSpeed(50);
            replay.play();
            Await.until("replay finished", () -> replay.state().finished());
            assertEquals(live.size(), replayed.size());
            for (int i = 0; i < live.size(); i++) {
                assertEquals(live.get(i).asReplayed(), replayed.get(i), "envelope " + i);
            }
            List<Integer> ids = new ArrayList<>(console.field().robots().robots().stream().map(RobotSnapshot::id).toList());
            assertEquals(List.of(1, 2), ids, "the replayed robots are in the model");
            assertTrue(console.field().robots().robots().stream().allMatch(RobotSnapshot::replayed), "and marked as replayed");
        }
    }
}
