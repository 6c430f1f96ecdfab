package touchline.fuzz;

import touchline.protocol.reliable.ReliableStream;

import java.util.ArrayList;
import java.util.List;

/**
 * The reliable stream fed a script read from the input: segments from the peer, sends and
 * polls at advancing times. Every segment it writes carries a sequence and an ack below the
 * modulus, and each segment from the peer is counted exactly once.
 */
final class ReliableStreamTarget implements FuzzTarget {

    private static final int FEED = 0;
    private static final int POLL = 1;
    private static final int SEND = 2;

    @Override
    public String name() {
        return "reliable";
    }

    @Override
    public void accept(byte[] input) {
        if (input.length == 0) {
            return;
        }
        int modulus = 2 + (input[0] & 0xFF) % (ReliableStream.MAX_MODULUS - 1);
        List<byte[]> out = new ArrayList<>();
        long[] delivered = {0};
        ReliableStream stream = new ReliableStream(modulus, 100, 1000, out::add, p -> delivered[0]++, 0);
        long now = 0;
        long fed = 0;
        long pureAcks = 0;
        int at = 1;
        while (at < input.length) {
            int op = (input[at++] & 0xFF) % 3;
            int n = at < input.length ? input[at++] & 0xFF : 0;
            n = Math.min(n, input.length - at);
            if (op == FEED) {
                byte[] segment = java.util.Arrays.copyOfRange(input, at, at + n);
                at += n;
                stream.input(segment, now);
                fed++;
                boolean valid = segment.length >= 2 && (segment[0] & 0xFF) < modulus && (segment[1] & 0xFF) < modulus;
                pureAcks += valid && segment.length == 2 ? 1 : 0;
            } else if (op == POLL) {
                now += n * 7L;
                stream.poll(now);
            } else {
                stream.send(java.util.Arrays.copyOfRange(input, at, at + n), now);
                at += n;
            }
        }
        for (byte[] s : out) {
            FuzzTarget.check(s.length >= 2 && (s[0] & 0xFF) < modulus && (s[1] & 0xFF) < modulus,
                    "a segment with a sequence or ack beyond the modulus " + modulus);
        }
        ReliableStream.Stats stats = stream.stats();
        FuzzTarget.check(stats.delivered() == delivered[0], "delivered count differs from deliveries");
        FuzzTarget.check(stats.delivered() + stats.duplicates() + stats.invalid() + pureAcks == fed,
                "segments counted " + (stats.delivered() + stats.duplicates() + stats.invalid() + pureAcks) + " times, fed " + fed);
    }

    @Override
    public List<byte[]> seeds() {
        // modulus 21: a send, the peer's ack, a data segment from the peer, polls
        return List.of(new byte[]{19, SEND, 3, 'a', 'b', 'c', FEED, 2, 20, 0, FEED, 3, 0, 0, 'x', POLL, 20, POLL, 100},
                new byte[]{0, FEED, 4, 0, 1, 'h', 'i', FEED, 4, 0, 1, 'h', 'i', POLL, 1});
    }
}
