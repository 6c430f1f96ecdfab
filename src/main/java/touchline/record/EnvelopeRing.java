package touchline.record;

import touchline.transport.Envelope;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReferenceArray;

/**
 * The recorder's hand-off: a bounded ring that any number of publishing threads offer to
 * and one writer thread drains. An offer is one compare-and-set and one ordered store, with
 * no allocation (a linked queue allocates a node per envelope, which at half a million
 * datagrams a second is garbage the receiving thread pays for); a full ring refuses instead
 * of blocking, so the network thread never waits for the disk.
 */
final class EnvelopeRing {

    private final AtomicReferenceArray<Envelope> slots;
    private final int mask;
    private final AtomicLong tail = new AtomicLong();
    private long head;                 // the writer's own position
    private volatile long freedUpTo;   // what producers may reuse: the writer publishes it after a drain

    /** @param capacity rounded up to a power of two */
    EnvelopeRing(int capacity) {
        int size = Integer.highestOneBit(Math.max(2, capacity) - 1) << 1;
        slots = new AtomicReferenceArray<>(size);
        mask = size - 1;
    }

    int capacity() {
        return mask + 1;
    }

    /** False when the ring is full: the caller counts the envelope as dropped. */
    boolean offer(Envelope e) {
        long t;
        do {
            t = tail.get();
            if (t - freedUpTo >= slots.length()) {
                return false;
            }
        } while (!tail.compareAndSet(t, t + 1));
        slots.setRelease((int) t & mask, e);
        return true;
    }

    /** Writer thread only: the next envelope, or null when none is published yet. */
    Envelope poll() {
        int i = (int) head & mask;
        Envelope e = slots.getAcquire(i);
        if (e == null) {
            return null;
        }
        slots.setPlain(i, null);
        head++;
        return e;
    }

    /** Writer thread only: lets producers reuse the slots polled so far (once per batch, not per poll). */
    void release() {
        freedUpTo = head;
    }

    /** Envelopes accepted by {@link #offer} so far. */
    long offered() {
        return tail.get();
    }
}
