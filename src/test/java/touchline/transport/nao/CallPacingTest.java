package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import touchline.proto.Nao.HAWActorRPCRequest;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Per-method pacing alone, on a fake clock: times are plain numbers of nanoseconds. */
class CallPacingTest {

    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);
    private static final NaoLinkConfig CONFIG = NaoLinkConfig.parse("interval.ALMotion.moveToward = 100\n", "test");

    private static QueuedCall walk(float x, long madeAt) {
        return new QueuedCall(NaoCall.of("ALMotion", "moveToward", x, 0f, 0f), HAWActorRPCRequest.newBuilder(),
                1000, false, new CompletableFuture<>(), madeAt);
    }

    @Test
    void aCallInsideTheIntervalWaitsAndTheNewestReplacesTheWaitingOne() {
        assertEquals(100, CONFIG.minIntervalMillis(NaoCall.of("ALMotion", "moveToward")), CONFIG.problems().toString());
        CallPacing pacing = new CallPacing(CONFIG);
        QueuedCall first = walk(1, 0);
        assertFalse(pacing.holdIfEarly(first, 0), "the first call goes at once");
        pacing.sent(first.call(), 0);

        QueuedCall second = walk(0.5f, 10 * MS);
        QueuedCall stop = walk(0, 20 * MS);
        assertTrue(pacing.holdIfEarly(second, 10 * MS));
        assertTrue(pacing.holdIfEarly(stop, 20 * MS));
        assertEquals(new CallOutcome.Superseded(), second.future().getNow(null));
        assertEquals(100 * MS, pacing.nextDue(Long.MAX_VALUE));

        assertEquals(List.of(), pacing.due(99 * MS));
        assertEquals(List.of(stop), pacing.due(100 * MS), "the user's last input goes out at the interval's end");
        assertFalse(stop.future().isDone());
        assertEquals(0, pacing.waiting());
    }

    @Test
    void unpacedMethodsAndCallsAfterTheIntervalGoAtOnce() {
        CallPacing pacing = new CallPacing(CONFIG);
        QueuedCall say = new QueuedCall(NaoCall.of("ALTextToSpeech", "say", "hi"), HAWActorRPCRequest.newBuilder(),
                1000, false, new CompletableFuture<>(), 0);
        pacing.sent(say.call(), 0);
        assertFalse(pacing.holdIfEarly(say, 1));
        QueuedCall first = walk(1, 0);
        pacing.sent(first.call(), 0);
        assertFalse(pacing.holdIfEarly(walk(1, 100 * MS), 100 * MS));
    }

    @Test
    void aWaitingCallPastItsOwnTimeoutEndsAsTimedOut() {
        NaoLinkConfig slow = NaoLinkConfig.parse("interval.ALMotion.moveToward = 5000\n", "test");
        CallPacing pacing = new CallPacing(slow);
        pacing.sent(walk(1, 0).call(), 0);
        QueuedCall late = walk(0, 10 * MS);
        assertTrue(pacing.holdIfEarly(late, 10 * MS));
        assertEquals(List.of(), pacing.due(5000 * MS));
        assertEquals(new CallOutcome.TimedOut(1000), late.future().getNow(null));
        assertEquals(1, pacing.timeouts());
    }

    @Test
    void failAllEndsTheWaitingCalls() {
        CallPacing pacing = new CallPacing(CONFIG);
        pacing.sent(walk(1, 0).call(), 0);
        QueuedCall waiting = walk(0, 10 * MS);
        pacing.holdIfEarly(waiting, 10 * MS);
        CallOutcome.Lost lost = new CallOutcome.Lost("robot not connected");
        assertEquals(1, pacing.failAll(lost));
        assertEquals(lost, waiting.future().getNow(null));
        assertEquals(List.of(), pacing.due(Long.MAX_VALUE / 2));
    }
}
