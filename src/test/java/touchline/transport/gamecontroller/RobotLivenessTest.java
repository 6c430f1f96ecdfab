package touchline.transport.gamecontroller;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class RobotLivenessTest {

    @Test
    void onlineBelow2sLateBelow4sOfflineAfter() {
        RobotLiveness l = new RobotLiveness();
        assertEquals(RobotLiveness.Status.OFFLINE, l.status(13, 1, 0));
        l.heard(13, 1, 10_000);
        assertEquals(RobotLiveness.Status.ONLINE, l.status(13, 1, 11_999));
        assertEquals(RobotLiveness.Status.LATE, l.status(13, 1, 12_000));
        assertEquals(RobotLiveness.Status.LATE, l.status(13, 1, 13_999));
        assertEquals(RobotLiveness.Status.OFFLINE, l.status(13, 1, 14_000));
        assertEquals(RobotLiveness.Status.OFFLINE, l.status(13, 2, 11_000));
        assertEquals(1, l.all(11_000).size());
    }
}
