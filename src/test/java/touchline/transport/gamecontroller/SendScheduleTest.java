package touchline.transport.gamecontroller;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The send schedule as a pure calculation on a millisecond scale. */
class SendScheduleTest {

    /** Sends every due datagram up to {@code until}, on time, and returns their times. */
    private static List<Long> run(SendSchedule s, long until) {
        List<Long> times = new ArrayList<>();
        while (s.next() <= until) {
            times.add(s.next());
            s.sent(s.next(), s.next());
        }
        return times;
    }

    @Test
    void hslStopSendsAtOnceThenEvery200MsFiveTimesThenTheGridFromTheLast() {
        SendSchedule s = SendSchedule.burstOnStop(0, 500, 200);
        assertEquals(List.of(0L, 500L, 1000L), run(s, 1200));
        assertFalse(s.changed(1250, false), "an ordinary change waits for the grid");
        assertEquals(1500, s.next());
        s.changed(1250, true);
        assertEquals(List.of(1250L, 1450L, 1650L, 1850L, 2050L, 2550L, 3050L), run(s, 3100));
        s.changed(3100, true);
        assertEquals(3550, s.next(), "still stopped: no new burst");
        s.changed(3200, false);
        assertEquals(3550, s.next(), "resuming changes nothing");
    }

    @Test
    void aLateBurstDatagramIsNotSkippedButTheGridIs() {
        SendSchedule s = SendSchedule.burstOnStop(0, 500, 200);
        s.changed(100, true);
        s.sent(100, 100);
        s.sent(300, 700); // the second went out 400 ms late
        assertEquals(500, s.next(), "the third is due at once");
        s.sent(500, 700);
        s.sent(700, 700);
        s.sent(900, 2000); // the fifth, then the grid skips what it missed
        assertEquals(2400, s.next());
    }

    @Test
    void aDatagramInFlightWhenPlayStopsIsNotTheBurstsFirst() {
        SendSchedule s = SendSchedule.burstOnStop(0, 500, 200);
        s.sent(0, 0);
        s.changed(501, true); // play stopped while the datagram due at 500 was being sent
        s.sent(500, 502);
        assertEquals(501, s.next(), "the burst still starts with a datagram of its own");
    }

    @Test
    void olderFormatsSendAnExtraDatagramAfterEveryChangeWithoutMovingTheGrid() {
        SendSchedule s = SendSchedule.everyChange(0, 500);
        s.sent(0, 0);
        assertTrue(s.changed(120, false));
        assertTrue(s.changed(130, true));
        assertEquals(500, s.next());
        s.sent(500, 1700); // a stall: missed slots are skipped
        assertEquals(2000, s.next());
    }
}
