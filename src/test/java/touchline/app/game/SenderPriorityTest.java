package touchline.app.game;

import org.junit.jupiter.api.Test;
import touchline.transport.gamecontroller.GcSender;

import static org.junit.jupiter.api.Assertions.*;

/** The sender's real-time outcome in words, as the value the GameController tab switches on. */
class SenderPriorityTest {

    @Test
    void eachOfTheSendersOutcomesIsItsOwnKind() {
        assertEquals(new SenderPriority(SenderPriority.Kind.REAL_TIME, ""), SenderPriority.of(""));
        assertEquals(new SenderPriority(SenderPriority.Kind.NOT_REQUESTED, ""), SenderPriority.of(GcSender.NOT_REQUESTED));
        assertEquals(new SenderPriority(SenderPriority.Kind.STARTING, ""), SenderPriority.of(GcSender.NOT_STARTED));
        assertEquals(new SenderPriority(SenderPriority.Kind.REFUSED, "Operation not permitted"),
                SenderPriority.of("Operation not permitted"));
    }
}
