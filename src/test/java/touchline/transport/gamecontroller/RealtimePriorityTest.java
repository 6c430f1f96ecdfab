package touchline.transport.gamecontroller;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The portable fallback for the GameController sender: normal priority off Linux or when switched off. */
class RealtimePriorityTest {

    @Test
    void offLinuxTheThreadKeepsNormalPriorityAndSaysWhy() {
        RealtimePriority p = new RealtimePriority(10, "Mac OS X", true);
        assertEquals("real-time priority only on Linux, this is Mac OS X", p.unavailable());
        assertEquals("real-time priority only on Linux, this is Mac OS X", p.applyToCurrentThread());
        assertEquals("real-time priority only on Linux, this is Windows 11", new RealtimePriority(10, "Windows 11", true).unavailable());
    }

    @Test
    void switchedOffItNeverAsksEvenOnLinux() {
        RealtimePriority p = new RealtimePriority(10, "Linux", false);
        assertEquals("switched off (-Dtouchline.realtime=off)", p.unavailable());
        assertEquals("switched off (-Dtouchline.realtime=off)", p.applyToCurrentThread());
    }

    @Test
    void onLinuxItMayBeHad() {
        assertEquals("", new RealtimePriority(10, "Linux", true).unavailable());
    }
}
