package touchline.serve;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** A viewer's queue: everything in order while it keeps up, the newest per subscription when it does not. */
class PendingMessagesTest {

    private final Subscription a = new Subscription(null, 1, null);
    private final Subscription b = new Subscription(null, 2, null);

    private static byte[] v(int n) {
        return new byte[]{(byte) n};
    }

    private static List<String> drain(PendingMessages q) {
        List<String> out = new ArrayList<>();
        for (PendingMessages.Pending p = q.poll(); p != null; p = q.poll()) {
            out.add(p.subscription.id() + ":" + p.payload[0] + "@" + p.timeNanos);
        }
        return out;
    }

    @Test
    void aViewerThatKeepsUpGetsEveryMessageInOrder() {
        PendingMessages q = new PendingMessages(8);
        q.offer(a, 1, v(1), false);
        q.offer(b, 2, v(2), false);
        q.offer(a, 3, v(3), false);
        assertEquals(List.of("1:1@1", "2:2@2", "1:3@3"), drain(q));
        assertEquals(0, q.dropped());
    }

    @Test
    void aSlowViewerKeepsTheNewestOfEachSubscriptionInItsPlace() {
        PendingMessages q = new PendingMessages(8);
        q.offer(a, 1, v(1), true);
        q.offer(b, 2, v(2), true);
        q.offer(a, 3, v(3), true);
        q.offer(a, 4, v(4), true);
        assertEquals(List.of("1:4@4", "2:2@2"), drain(q));
        assertEquals(2, q.dropped());
    }

    @Test
    void aFullQueueReplacesRatherThanGrows() {
        PendingMessages q = new PendingMessages(2);
        q.offer(a, 1, v(1), false);
        q.offer(a, 2, v(2), false);
        q.offer(a, 3, v(3), false); // full: replaces the newest of a
        q.offer(b, 4, v(4), false); // full, nothing of b waits: the oldest gives way
        assertEquals(2, q.size());
        assertEquals(List.of("1:3@3", "2:4@4"), drain(q));
        assertEquals(2, q.dropped());
        q.offer(a, 5, v(5), true); // nothing of a waits any more: queued, not a replacement
        assertEquals(List.of("1:5@5"), drain(q));
    }
}
