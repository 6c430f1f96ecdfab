package touchline.app.game;

import org.junit.jupiter.api.Test;

import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class RivalGameControllersTest {

    /** 10 000 rivals from made-up ports: the warning and the table keep the last 64, the rest are counted. */
    @Test
    void aFloodOfRivalsKeepsTheLastOnes() {
        RivalGameControllers rivals = new RivalGameControllers();
        for (int port = 1; port <= 10_000; port++) {
            rivals.heard(new InetSocketAddress("127.0.0.1", port), "gc.unknown", null, 1000);
        }
        assertEquals(RecentSources.CAPACITY, rivals.active(1000).size());
        assertEquals(10_000 - RecentSources.CAPACITY, rivals.forgotten());
        assertTrue(rivals.active(1000).containsKey("127.0.0.1:10000"));
        assertTrue(rivals.warning(1000).startsWith("WARNING: ANOTHER GAMECONTROLLER"), rivals.warning(1000));
    }
}
