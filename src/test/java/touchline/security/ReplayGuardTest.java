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
    void aRestartIsANewBootIdAndAnEarlierBootIsAReplay() {
        ReplayGuard g = new ReplayGuard();
        assertTrue(g.check(3, counter(0x9000_0000, 500)).accepted());
        ReplayGuard.Verdict restart = g.check(3, counter(0x1234, 1));
        assertTrue(restart.accepted());
        assertTrue(restart.restarted(), "a lower counter of a new boot is a restart, not a replay");
        assertFalse(g.check(3, counter(0x9000_0000, 501)).accepted(), "a capture of the earlier boot");
        assertTrue(g.check(3, counter(0x1234, 2)).accepted());
    }

    @Test
    void countersAboveTheSignBitCompareUnsigned() {
        ReplayGuard g = new ReplayGuard();
        assertTrue(g.check(1, counter(0xF000_0000, 1)).accepted());
        assertTrue(g.check(1, counter(0xF000_0000, 2)).accepted());
        assertFalse(g.check(1, counter(0xF000_0000, 1)).accepted());
    }
}
