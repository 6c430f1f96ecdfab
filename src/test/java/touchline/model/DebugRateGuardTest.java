package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.model.store.StoreEnvelopes;
import touchline.proto.Fumanoid;
import touchline.transport.Envelope;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Robots over the league's debug-packet limit during play, on a manual clock. */
class DebugRateGuardTest {

    private final long[] now = {5_000_000_000L};

    private static RuleProfile profile(String name) throws RuleProfileException {
        return RuleProfile.named(name);
    }

    private Envelope status(int robot, String gameState) {
        return StoreEnvelopes.in(now[0], robot, "status", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).setGameState(gameState).build())
                .build());
    }

    /** {@code seconds} of keep-alives every {@code periodMillis} from both robots. */
    private void run(DebugRateGuard guard, int seconds, long periodMillis, String stateOf1, String stateOf2) {
        for (long t = 0; t < seconds * 1000L; t += periodMillis) {
            guard.accept(status(1, stateOf1));
            guard.accept(status(2, stateOf2));
            now[0] += periodMillis * 1000;
        }
    }

    @Test
    void aLabKeepAliveDuringPlayIsFlaggedAndTheGameRateIsNot() throws Exception {
        DebugRateGuard lab = new DebugRateGuard(() -> now[0], profile("hsl-2026"));
        run(lab, 12, 200, "PLAYING", "INITIAL");
        List<DebugRateGuard.OverLimit> over = lab.overLimit();
        assertEquals(1, over.size(), "robot 2 is not in play: its lab rate is allowed");
        assertEquals(1, over.get(0).robotId());
        assertEquals(5.0, over.get(0).perSecond(), 0.01);
        assertTrue(over.get(0).describe().contains("PLAYING"), over.get(0).describe());

        DebugRateGuard game = new DebugRateGuard(() -> now[0], profile("hsl-2026"));
        run(game, 12, 1000, "PLAYING", "READY");
        assertTrue(game.overLimit().isEmpty(), "one a second is the limit, not over it");
    }

    @Test
    void aProfileWithoutADebugLimitFlagsNobody() throws Exception {
        DebugRateGuard lab = new DebugRateGuard(() -> now[0], profile("lab"));
        run(lab, 12, 200, "PLAYING", "PLAYING");
        assertTrue(lab.overLimit().isEmpty());
    }
}
