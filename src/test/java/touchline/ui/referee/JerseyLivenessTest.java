package touchline.ui.referee;

import org.junit.jupiter.api.Test;
import touchline.model.RobotSnapshot;
import touchline.transport.gamecontroller.RobotLiveness;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A jersey's liveness agrees with the Robots view; return packets only judge robots that view does not list. */
class JerseyLivenessTest {

    private static RobotSnapshot robot(int id, int team, boolean online) {
        return new RobotSnapshot(id, "r" + id, team, 80, "", "", "", 0, 0, 0, false, 10, 0, 0, online, 1, 1, 1, 0, 0,
                null, touchline.transport.Origin.LIVE);
    }

    @Test
    void theRobotsViewWinsAndReturnPacketsJudgeTheRest() {
        RobotLiveness returns = new RobotLiveness();
        returns.heard(13, 1, 10_000); // return packets say online...
        returns.heard(13, 3, 10_000);
        returns.heard(7, 2, 5_000);
        JerseyLiveness l = new JerseyLiveness(List.of(robot(1, 13, false), robot(2, 13, true)), returns, 10_500);
        assertEquals("offline", l.status(13, 1), "...but the Robots view says offline: the tab says the same");
        assertEquals("online", l.status(13, 2), "listed by the Robots view, no return packets");
        assertEquals("online", l.status(13, 3), "unknown to the Robots view: its return packets");
        assertEquals("offline", l.status(7, 2), "last return packet 5.5 s ago");
        assertEquals("–", l.status(7, 4), "never heard");
    }
}
