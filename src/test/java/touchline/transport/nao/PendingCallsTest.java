package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import touchline.proto.Nao.HAWActorRPCRequest;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

/** The call table alone, on a fake clock: times are plain numbers of nanoseconds. */
class PendingCallsTest {

    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);

    private static QueuedCall call(String method, long timeoutMillis, long madeAt) {
        return new QueuedCall(NaoCall.of("ALMotion", method), HAWActorRPCRequest.newBuilder(), timeoutMillis, true,
                new CompletableFuture<>(), madeAt);
    }

    @Test
    void aReplyEndsItsOwnCallByIdWhateverTheOrder() {
        PendingCalls table = new PendingCalls();
        QueuedCall first = call("a", 100, 0);
        QueuedCall second = call("b", 100, 0);
        long id1 = table.nextId();
        table.sent(id1, first, 100 * MS, 1);
        long id2 = table.nextId();
        table.sent(id2, second, 100 * MS, 1);
        assertNotEquals(id1, id2);

        assertSame(second, table.answered(id2).call());
        assertSame(first, table.answered(id1).call());
        assertEquals(0, table.size());
        assertEquals(0, table.strays());
    }

    @Test
    void aCallPastItsDeadlineExpiresAndItsLateReplyIsCountedAndDropped() {
        PendingCalls table = new PendingCalls();
        QueuedCall slow = call("slow", 100, 0);
        QueuedCall later = call("later", 100, 50 * MS);
        long slowId = table.nextId();
        table.sent(slowId, slow, 100 * MS, 1);
        table.sent(table.nextId(), later, 150 * MS, 1);
        assertEquals(100 * MS, table.nextDeadline(Long.MAX_VALUE));

        assertEquals(List.of(), table.expired(99 * MS), "not yet");
        List<PendingCalls.Sent> over = table.expired(100 * MS);
        assertEquals(1, over.size());
        assertSame(slow, over.get(0).call());
        table.timeOut(slow, 120 * MS);
        assertEquals(new CallOutcome.TimedOut(120), slow.future().getNow(null));
        assertEquals(1, table.timeouts());
        assertEquals(150 * MS, table.nextDeadline(Long.MAX_VALUE));

        assertNull(table.answered(slowId), "the late reply matches nothing");
        assertEquals(1, table.strays());
        assertFalse(later.future().isDone());
    }

    @Test
    void anUnreadableReplyIsNotAStray() {
        PendingCalls table = new PendingCalls();
        QueuedCall c = call("x", 100, 0);
        long id = table.nextId();
        table.sent(id, c, 100 * MS, 1);
        assertSame(c, table.unreadable(id).call());
        assertNull(table.unreadable(id));
        assertEquals(0, table.strays());
    }

    @Test
    void failAllEndsEveryPendingCallWithTheReason() {
        PendingCalls table = new PendingCalls();
        QueuedCall a = call("a", 100, 0);
        QueuedCall b = call("b", 100, 0);
        table.sent(table.nextId(), a, 100 * MS, 1);
        table.sent(table.nextId(), b, 100 * MS, 2);
        CallOutcome.Lost lost = new CallOutcome.Lost("disconnected (peer closed or heartbeat timed out)");

        assertEquals(2, table.failAll(lost));
        assertEquals(lost, a.future().getNow(null));
        assertEquals(lost, b.future().getNow(null));
        assertEquals(0, table.size());
        assertEquals(List.of(), table.expired(Long.MAX_VALUE / 2));
    }

    @Test
    void deadlinesCompareAcrossTheNanoClocksWrap() {
        PendingCalls table = new PendingCalls();
        long nearWrap = Long.MAX_VALUE - 10 * MS;
        QueuedCall c = call("w", 100, nearWrap);
        table.sent(table.nextId(), c, nearWrap + 100 * MS, 1); // overflows to a negative number
        assertEquals(List.of(), table.expired(nearWrap + 50 * MS));
        assertEquals(1, table.expired(nearWrap + 100 * MS).size());
    }
}
