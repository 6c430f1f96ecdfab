package touchline.bench.gc;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The benchmark's judgement of receive times, on synthetic times. */
class BurstTimingTest {

    private static long ms(double v) {
        return (long) (v * 1_000_000);
    }

    @Test
    void separatesStopLatencyBurstAndGrid() {
        long[] received = {ms(0), ms(500), ms(1000), ms(1251), ms(1452), ms(1650), ms(1850), ms(2050), ms(2553)};
        long[] stops = {ms(1250)};
        BurstTiming t = new BurstTiming(received, stops, 500, 200);
        assertEquals(1, t.stops());
        assertEquals(1.0, t.stopLatencyP99(), 1e-9);
        assertEquals(2.0, t.burstP99(), 1e-9, "1452 - 1251 = 201, then 198: the largest is 2 ms off");
        assertEquals(3.0, t.gridP99(), 1e-9, "2553 - 2050 = 503");
    }
}
