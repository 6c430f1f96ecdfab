package touchline.security;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class ReplayGuardTest {

    private static long counter(int boot, int seq) {
        return ((long) boot << 32) | (seq & 0xFFFFFFFFL);
    }

    @Test
    void newerCountersPassReplaysAndOldOnesDoNot() {
        ReplayGuard g = new ReplayGuard();
        assertTrue(g.check(3, counter(0xABCD, 1)).accepted());
        assertTrue(g.check(3, counter(0xABCD, 2)).accepted());
        assertFalse(g.check(3, counter(0xABCD, 2)).accepted(), "the same counter again");
        assertFalse(g.check(3, counter(0xABCD, 1)).accepted(), "an older counter");
        assertTrue(g.check(4, counter(0xABCD, 1)).accepted(), "each robot has its own counter");
    }

    @Test
    void aHigherBootIsARestartAndALowerBootIsAnEarlierOne() {
        ReplayGuard g = new ReplayGuard();
        assertEquals(ReplayGuard.Verdict.ACCEPTED, g.check(3, counter(0x1234, 500)));
        assertEquals(ReplayGuard.Verdict.RESTARTED, g.check(3, counter(0x1235, 1)),
                "a lower counter of the next boot is a restart, not a replay");
        assertEquals(ReplayGuard.Verdict.EARLIER_BOOT, g.check(3, counter(0x1234, 501)), "a capture of the earlier boot");
        assertEquals(ReplayGuard.Verdict.EARLIER_BOOT, g.check(3, counter(0x0001, 9)));
        assertEquals(ReplayGuard.Verdict.ACCEPTED, g.check(3, counter(0x1235, 2)), "the current boot goes on");
    }

    @Test
    void countersAboveTheSignBitCompareUnsigned() {
        ReplayGuard g = new ReplayGuard();
        assertTrue(g.check(1, counter(0xF000_0000, 1)).accepted());
        assertTrue(g.check(1, counter(0xF000_0000, 2)).accepted());
        assertFalse(g.check(1, counter(0xF000_0000, 1)).accepted());
    }
}
