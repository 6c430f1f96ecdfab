package touchline.protocol.reliable;

import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

/** Two stream ends over a simulated link that drops, duplicates and reorders, in virtual time. */
class ReliableStreamTest {

    /** A link with impairments; delivers in steps of virtual time. */
    static final class LossyLink {
        final Random random;
        final double drop, duplicate, reorder;
        final List<byte[]> toA = new ArrayList<>(), toB = new ArrayList<>();
        long impaired;

        LossyLink(long seed, double drop, double duplicate, double reorder) {
            random = new Random(seed);
            this.drop = drop;
            this.duplicate = duplicate;
            this.reorder = reorder;
        }

        void send(List<byte[]> queue, byte[] d) {
            if (random.nextDouble() < drop) {
                impaired++;
                return;
            }
            if (random.nextDouble() < reorder && !queue.isEmpty()) {
                queue.add(queue.size() - 1, d); // overtakes the one before it
                impaired++;
            } else {
                queue.add(d);
            }
            if (random.nextDouble() < duplicate) {
                queue.add(d.clone());
                impaired++;
            }
        }

        static void deliver(List<byte[]> queue, ReliableStream to, long now) {
            List<byte[]> batch = new ArrayList<>(queue);
            queue.clear();
            for (byte[] d : batch) {
                to.input(d, now);
            }
        }
    }

    private static final String LOREM = ("Lorem ipsum dolor sit amet, consectetur adipiscing elit, sed do eiusmod tempor "
            + "incididunt ut labore et dolore magna aliqua. ").repeat(60);

    @Test
    void loremIpsumArrivesWholeAndInOrderUnderHeavyLoss() {
        LossyLink link = new LossyLink(42, 0.2, 0.1, 0.1);
        ByteArrayOutputStream received = new ByteArrayOutputStream();
        long[] now = {0};
        ReliableStream a = new ReliableStream(21, 100, 250, d -> link.send(link.toB, d), p -> { }, 0);
        ReliableStream b = new ReliableStream(21, 100, 250, d -> link.send(link.toA, d), received::writeBytes, 0);
        byte[] text = LOREM.getBytes(StandardCharsets.US_ASCII);
        int offset = 0;
        while (received.size() < text.length && now[0] < 3_600_000) {
            if (a.canSend() && offset < text.length) {
                int n = Math.min(97, text.length - offset);
                assertTrue(a.send(java.util.Arrays.copyOfRange(text, offset, offset + n), now[0]));
                offset += n;
            }
            now[0] += 10;
            LossyLink.deliver(link.toB, b, now[0]);
            LossyLink.deliver(link.toA, a, now[0]);
            a.poll(now[0]);
            b.poll(now[0]);
        }
        assertEquals(LOREM, received.toString(StandardCharsets.US_ASCII));
        assertTrue(a.stats().retransmissions() > 0, "the link did lose segments");
        assertTrue(b.stats().duplicates() > 0, "the link did duplicate segments");
        assertTrue(link.impaired > 0.2 * (a.stats().dataSent() + a.stats().retransmissions()), "impairment rate");
    }

    @Test
    void matheAgreesBothWaysAtOnceUnderLoss() {
        LossyLink link = new LossyLink(7, 0.2, 0.1, 0.1);
        Mathe ma = new Mathe(300, 1), mb = new Mathe(300, 2);
        ReliableStream a = new ReliableStream(21, 100, 250, d -> link.send(link.toB, d), ma::receive, 0);
        ReliableStream b = new ReliableStream(21, 100, 250, d -> link.send(link.toA, d), mb::receive, 0);
        byte[] pa = ma.next(), pb = mb.next();
        long now = 0;
        while (!(ma.peerEnded() && mb.peerEnded()) && now < 3_600_000) {
            if (pa != null && a.send(pa, now)) {
                pa = ma.next();
            }
            if (pb != null && b.send(pb, now)) {
                pb = mb.next();
            }
            now += 10;
            LossyLink.deliver(link.toB, b, now);
            LossyLink.deliver(link.toA, a, now);
            a.poll(now);
            b.poll(now);
        }
        assertTrue(ma.agrees(), ma.summary());
        assertTrue(mb.agrees(), mb.summary());
    }

    @Test
    void matheNoticesWhenSomethingSlipsThrough() {
        Mathe m = new Mathe(3, 1);
        m.receive("OP 3".getBytes(StandardCharsets.US_ASCII));
        m.receive("OP 3".getBytes(StandardCharsets.US_ASCII)); // a duplicate the stream should have dropped
        m.receive("END 3 1".getBytes(StandardCharsets.US_ASCII));
        assertFalse(m.agrees(), m.summary());
        assertEquals(3, Mathe.fold(0, 1, 3));
        assertEquals(12, Mathe.fold(3, 2, 4));
    }

    @Test
    void invalidSegmentsAreCountedAndIgnored() {
        List<byte[]> out = new ArrayList<>();
        ReliableStream s = new ReliableStream(21, 100, 250, out::add, p -> fail("nothing to deliver"), 0);
        s.input(new byte[]{1}, 0);
        s.input(new byte[]{30, 0, 'x'}, 0);
        s.input(new byte[]{0, 21}, 0);
        assertEquals(3, s.stats().invalid());
        assertThrows(IllegalArgumentException.class, () -> new ReliableStream(43, 1, 1, out::add, p -> { }, 0));
        assertFalse(s.send(new byte[ReliableStream.MAX_PAYLOAD + 1], 0));
    }

    @Test
    void goldenSegmentsMatchTheFirmware() {
        List<byte[]> out = new ArrayList<>();
        ReliableStream s = new ReliableStream(21, 100, 250, out::add, p -> { }, 0);
        s.send(new byte[]{'h', 'i'}, 0);
        assertArrayEquals(new byte[]{0, 20, 'h', 'i'}, out.get(0), "seq 0, ack 20 (nothing received yet)");
        s.input(new byte[]{0, 0, 'y', 'o'}, 5); // peer's data 0, acking our 0
        assertTrue(s.canSend());
        s.poll(6);
        Iterator<byte[]> it = out.iterator();
        it.next();
        assertArrayEquals(new byte[]{0, 0}, it.next(), "pure ack of their 0");
    }
}
