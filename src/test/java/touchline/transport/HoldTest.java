package touchline.transport;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The gate's answer is a value; each sender words it for what it does with a held message. */
class HoldTest {

    @Test
    void matchModeSaysWhatBecomesOfAHeldRequestAndAHeldCommand() {
        Hold play = Hold.untilPlayStops("match mode, PLAYING");
        assertEquals("match mode, PLAYING; goes out when play stops", play.queued());
        assertEquals("match mode, PLAYING; not sent", play.dropped());
    }

    @Test
    void aHoldForGoodPromisesNothing() {
        Hold off = Hold.always("viewing a remote Touchline: commands are off");
        assertEquals("viewing a remote Touchline: commands are off", off.queued());
        assertEquals("viewing a remote Touchline: commands are off", off.dropped());
    }
}
