package touchline.model.store;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class TextLogTest {

    @Test
    void keepsLinesTimeStampedPerRobotAndBounded() {
        TextLog log = new TextLog(50);
        for (int i = 0; i < 100; i++) {
            log.accept(StoreEnvelopes.text(1_000 + i, i % 2 + 1, "demo.text", "line " + i));
        }
        assertEquals(50, log.size());
        var robot2 = log.since(0, 2, 1000);
        assertEquals(25, robot2.size());
        assertEquals("line 99", robot2.get(robot2.size() - 1).value().text());
        assertEquals(1_099, robot2.get(robot2.size() - 1).value().timeMicros());
        assertEquals(2, robot2.get(0).value().robotId());
        assertEquals(50, log.since(0, -1, 1000).size());
    }

    @Test
    void ignoresEverythingButDebugText() {
        TextLog log = new TextLog(10);
        log.accept(StoreEnvelopes.plot(1, 1, "demo.plotter", "sin", 0.5));
        assertEquals(0, log.version());
    }
}
