package touchline.ui.frame;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The cap on data frames ({@code console --max-fps}), over JavaFX's 60 pulses a second in made-up time. */
class FrameCapTest {

    /** Data frames pulled in one second of pulses 1/60 s apart, every pulse bringing a change. */
    private static int framesInOneSecond(FrameCap cap) {
        long last = Long.MIN_VALUE / 2;
        int frames = 0;
        for (int pulse = 0; pulse < 60; pulse++) {
            long now = pulse * 1_000_000_000L / 60;
            if (!cap.holdsBack(now, last)) {
                last = now;
                frames++;
            }
        }
        return frames;
    }

    @Test
    void theDefaultPullsEveryOtherPulseAndALowerCapFewer() {
        assertEquals(30, FrameCap.standard().perSecond());
        assertEquals(33_000_000L, FrameCap.standard().minNanos(), "the 33 ms the console always had");
        assertEquals(30, framesInOneSecond(FrameCap.standard()));
        assertEquals(15, framesInOneSecond(new FrameCap(15)));
        assertEquals(10, framesInOneSecond(new FrameCap(10)));
        assertEquals(60, framesInOneSecond(new FrameCap(60)), "60: every pulse");
        assertEquals(1, framesInOneSecond(new FrameCap(1)));
    }

    @Test
    void aCapOutsideOneToSixtyIsRefusedWithTheReason() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new FrameCap(0));
        assertEquals("--max-fps must be between 1 and 60 frames a second, not 0", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new FrameCap(61));
    }
}
