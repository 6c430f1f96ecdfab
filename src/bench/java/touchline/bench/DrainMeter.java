package touchline.bench;

import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The ingest benchmark's default measurement: how fast a receiver empties a socket buffer
 * that was filled while it was held.
 */
final class DrainMeter {

    /** Holding the receiver while its socket buffer is filled, or letting it go. */
    @FunctionalInterface
    interface Step {
        void run() throws InterruptedException;
    }

    private final java.util.function.LongFunction<byte[]> source;
    private final int batch;
    /** Every thread's run and run-queue wait during the drains (the kernel's books), for {@code --threads}. */
    private final SchedStats sched = new SchedStats();
    private long drained;

    /** @param batch datagrams per filled buffer (made smaller when the kernel does not take a batch whole) */
    DrainMeter(List<byte[]> datagrams, int batch) {
        this(i -> datagrams.get((int) (i % datagrams.size())), batch);
    }

    /** @param source the n-th datagram to send (e.g. tagged with a fresh counter); called while the receiver is held */
    DrainMeter(java.util.function.LongFunction<byte[]> source, int batch) {
        this.source = source;
        this.batch = batch;
    }

    /**
     * Drain mode: with the receiver paused, fill its socket buffer with {@code batch}
     * datagrams, let it go and time until it has decoded them all; repeated for {@code secs}
     * seconds. Rate = datagrams decoded / time spent draining. The sender is idle while the
     * receiver works, so on two cores the figure is the receiver's own capacity, not a share
     * of a core it fights the sender for. A batch the kernel did not take whole (buffer full)
     * is left out and the batch made smaller.
     */
    IngestResult measure(int port, int secs, DecodedCounter decoded, Step pause, Step resume) throws Exception {
        try (DatagramChannel out = DatagramChannel.open()) {
            out.connect(new InetSocketAddress("127.0.0.1", port));
            pause.run();
            ThreadCpu cpu = new ThreadCpu();
            long decodedAll = 0; // batches left out included: their CPU is counted too
            long end = System.nanoTime() + secs * 1_000_000_000L;
            long sent = 0;
            long received = 0;
            long drainingNanos = 0;
            int size = batch;
            int incomplete = 0;
            while (System.nanoTime() < end) {
                long before = decoded.sum();
                for (int i = 0; i < size; i++) {
                    out.write(ByteBuffer.wrap(source.apply(sent)));
                    sent++;
                }
                if (decoded.sum() != before) {
                    throw new IllegalStateException("the receiver read while paused");
                }
                decoded.expect(before + size);
                cpu.begin();
                sched.begin();
                long t0 = System.nanoTime();
                resume.run();
                // parked, not spinning: the second core stays free for the receiver's own threads
                long t1 = decoded.await(t0 + 1_000_000_000L);
                pause.run();
                cpu.end();
                sched.end();
                long got = decoded.sum() - before;
                decodedAll += got;
                if (got < size) {
                    incomplete++;
                    size = Math.max(100, size * 3 / 4);
                    continue;
                }
                drainingNanos += t1 - t0;
                received += got;
            }
            resume.run();
            drained = decodedAll;
            if (incomplete > 0) {
                System.out.printf("  (%d batches not taken whole by the kernel, left out; batch now %d)%n", incomplete, size);
            }
            Map<String, Double> cpuPerMessage = new TreeMap<>();
            double perDatagram = 1.0 / Math.max(1, decodedAll);
            cpu.total().forEach((role, ns) -> cpuPerMessage.put(role, ns * perDatagram));
            return new IngestResult(received, received, received / (drainingNanos / 1e9), cpuPerMessage);
        }
    }

    /** After {@link #measure}: the threads that ran most during the drains, per datagram. */
    String threadsText() {
        return SchedStats.text(sched.total(), drained, 7);
    }
}
