package touchline.ui.frame;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

class PacedTextTest {

    private final PacedText text = new PacedText();

    @Test
    void aChangeAfterAQuietHalfSecondShowsAtOnce() {
        assertEquals("waiting", text.offer("waiting", 0));
        assertEquals("5 points", text.offer("5 points", 600_000));
    }

    @Test
    void changesWithinHalfASecondWaitAndTheLastOneShows() {
        text.offer("1 point", 1_000_000);
        assertNull(text.offer("2 points", 1_100_000));
        assertNull(text.offer("3 points", 1_200_000));
        assertNull(text.due(1_499_999));
        assertEquals("3 points", text.due(1_500_000), "the newest waiting text, once its turn came");
        assertNull(text.due(2_500_000), "nothing waits any more");
    }

    @Test
    void theSameTextIsNoChangeAndCancelsAWaitingOne() {
        assertEquals("a", text.offer("a", 0));
        assertNull(text.offer("b", 150_000), "sooner than half a second after \"a\": waits");
        assertNull(text.offer("a", 200_000), "back to what is shown: nothing to do");
        assertNull(text.due(5_000_000), "nothing waits any more");
        assertNull(text.offer("a", 6_000_000), "the text shown is no change, however late");
    }
}
