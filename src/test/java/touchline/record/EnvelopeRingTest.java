package touchline.record;

import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

class EnvelopeRingTest {

    private static Envelope envelope(long n) {
        return new Envelope(n, Direction.IN, Channel.GAMECONTROLLER, null, Envelope.NO_ROBOT, "gc", null, new byte[]{1},
                null);
    }

    @Test
    void keepsOrderRefusesWhenFullAndReusesSlotsOnlyAfterRelease() {
        EnvelopeRing ring = new EnvelopeRing(3);
        assertEquals(4, ring.capacity());
        List<Envelope> in = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            in.add(envelope(i));
            assertTrue(ring.offer(in.get(i)));
        }
        assertFalse(ring.offer(envelope(99)), "a full ring refuses");
        assertSame(in.get(0), ring.poll());
        assertFalse(ring.offer(envelope(99)), "a polled slot is reused only after release()");
        ring.release();
        Envelope fifth = envelope(4);
        assertTrue(ring.offer(fifth));
        assertSame(in.get(1), ring.poll());
        assertSame(in.get(2), ring.poll());
        assertSame(in.get(3), ring.poll());
        assertSame(fifth, ring.poll());
        assertNull(ring.poll());
        assertEquals(5, ring.offered());
    }

    @Test
    void manyProducersLoseNothingTheRingTook() throws Exception {
        EnvelopeRing ring = new EnvelopeRing(1024);
        int producers = 4;
        int each = 50_000;
        CountDownLatch start = new CountDownLatch(1);
        long[] refused = new long[producers];
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < producers; p++) {
            int id = p;
            Thread t = new Thread(() -> {
                try {
                    start.await();
                } catch (InterruptedException e) {
                    return;
                }
                for (int i = 0; i < each; i++) {
                    if (!ring.offer(envelope((long) id * each + i))) {
                        refused[id]++;
                    }
                }
            });
            t.start();
            threads.add(t);
        }
        start.countDown();
        Set<Long> seen = new HashSet<>();
        long[] lastPerProducer = new long[producers];
        java.util.Arrays.fill(lastPerProducer, -1);
        while (threads.stream().anyMatch(Thread::isAlive) || seen.size() < ring.offered()) {
            for (Envelope e; (e = ring.poll()) != null; ) {
                assertTrue(seen.add(e.timeMicros()), "delivered once");
                int producer = (int) (e.timeMicros() / each);
                assertTrue(e.timeMicros() > lastPerProducer[producer], "each producer's envelopes in order");
                lastPerProducer[producer] = e.timeMicros();
            }
            ring.release();
        }
        long totalRefused = java.util.Arrays.stream(refused).sum();
        assertEquals((long) producers * each, seen.size() + totalRefused);
        assertEquals(seen.size(), ring.offered());
    }
}
