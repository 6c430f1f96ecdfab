package touchline.bench.bridges;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class DeliveryTest {

    @Test
    void lostIsWhatTheRobotSentToSubscribersAndTheConsoleDidNotCount() {
        Delivery d = new Delivery("booster-1", 6_180, 6_150, 60);
        assertEquals(30, d.lost());
        assertEquals("| booster-1 | 6180 | 6150 | 30 | 102.5 |", d.row());
    }

    @Test
    void aMessageCountedInBeforeTheRobotCountedItsSubscriptionIsNotALoss() {
        assertEquals(0, new Delivery("booster-2", 100, 101, 1).lost());
    }

    @Test
    void cpuIsTheShareOfOneCoreSoTwoBusyCoresRead200() {
        CpuMeter meter = new CpuMeter(1_000_000_000L, 5_000_000_000L);
        assertEquals(25.0, meter.percentOfCore(1_500_000_000L, 7_000_000_000L), 1e-9);
        assertEquals(200.0, meter.percentOfCore(9_000_000_000L, 9_000_000_000L), 1e-9);
    }

    @Test
    void cpuIsUnknownWithoutWallTimeOrAProcessCpuClock() {
        assertEquals(Double.NaN, new CpuMeter(0, 10).percentOfCore(5, 10));
        assertEquals(Double.NaN, new CpuMeter(-1, 0).percentOfCore(-1, 10));
    }
}
