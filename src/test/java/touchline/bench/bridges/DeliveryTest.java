package touchline.bench.bridges;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class DeliveryTest {

    @Test
    void lostIsWhatTheRobotSentToSubscribersAndTheConsoleDidNotCount() {
        Delivery d = new Delivery("booster-1", 6_180, 6_150, 0, 0, 60);
        assertEquals(30, d.lost());
        assertEquals("| booster-1 | 6180 | 6150 | 30 | 0 | 0 | 102.5 |", d.row());
    }

    @Test
    void theRowSaysWhatTheConsoleCountedButCouldNotUseBesideTheLoss() {
        Delivery d = new Delivery("booster-3", 6_180, 6_177, 3, 2, 60);
        assertEquals(3, d.lost());
        assertEquals("| booster-3 | 6180 | 6177 | 3 | 3 | 2 | 103.0 |", d.row());
        assertEquals(d.row().split("\\|").length, Delivery.header().lines().findFirst().orElseThrow().split("\\|").length);
    }

    @Test
    void aMessageCountedInBeforeTheRobotCountedItsSubscriptionIsNotALoss() {
        assertEquals(0, new Delivery("booster-2", 100, 101, 0, 0, 1).lost());
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
