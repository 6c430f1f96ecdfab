package touchline.bench.gc;

import touchline.transport.gamecontroller.RealtimePriority;
import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.Locale;

/**
 * Receives a GameController's datagrams on 127.0.0.1 and measures the intervals between them
 * against the nominal period: what a robot on the field sees of the sender's cadence. Used by
 * {@code bench gc} and by {@code bench ui --gc} (the sender inside the loaded console).
 * With {@code realtime} the receiving thread asks for SCHED_RR, so its own wake-up delay does
 * not count against the sender.
 */
public final class GcIntervalProbe implements AutoCloseable {

    private final DatagramSocket socket;
    private final long intervalMs;
    private final boolean realtime;
    private final Object lock = new Object();
    private long[] nanos = new long[1024];
    private int count;

    public GcIntervalProbe(String name, long intervalMs, boolean realtime) throws IOException {
        this.intervalMs = intervalMs;
        this.realtime = realtime;
        socket = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        Thread thread = new Thread(this::loop, name);
        thread.setDaemon(true);
        thread.setPriority(Thread.MAX_PRIORITY);
        thread.start();
    }

    public InetSocketAddress address() {
        return (InetSocketAddress) socket.getLocalSocketAddress();
    }

    private void loop() {
        if (realtime) {
            new RealtimePriority(10).applyToCurrentThread();
        }
        byte[] buf = new byte[2048];
        DatagramPacket p = new DatagramPacket(buf, buf.length);
        while (!socket.isClosed()) {
            try {
                socket.receive(p);
                long t = System.nanoTime();
                synchronized (lock) {
                    if (count == nanos.length) {
                        nanos = Arrays.copyOf(nanos, count * 2);
                    }
                    nanos[count++] = t;
                }
            } catch (IOException e) {
                return;
            }
        }
    }

    /** Forgets what was received so far (the warm-up is not part of the measurement). */
    public void reset() {
        synchronized (lock) {
            count = 0;
        }
    }

    /** The receive times so far (System.nanoTime), in order. */
    public long[] receiveTimes() {
        synchronized (lock) {
            return Arrays.copyOf(nanos, count);
        }
    }

    /** Each interval's deviation from the nominal period, in ms (negative: early). */
    public double[] deviationsMs() {
        synchronized (lock) {
            double[] d = new double[Math.max(0, count - 1)];
            for (int i = 1; i < count; i++) {
                d[i - 1] = (nanos[i] - nanos[i - 1]) / 1e6 - intervalMs;
            }
            return d;
        }
    }

    /** One line: intervals, |deviation| p50 / p99 / max and the mean interval. */
    public String summary() {
        double[] dev = deviationsMs();
        if (dev.length == 0) {
            return "no intervals";
        }
        double[] abs = Arrays.stream(dev).map(Math::abs).sorted().toArray();
        double mean = Arrays.stream(dev).average().orElse(0);
        return String.format(Locale.ROOT,
                "intervals %d, |deviation from %d ms| p50 %.3f ms, p99 %.3f ms, max %.3f ms; mean interval %.3f ms",
                dev.length, intervalMs, percentile(abs, 50), percentile(abs, 99), abs[abs.length - 1], intervalMs + mean);
    }

    public static double percentile(double[] sorted, double p) {
        int i = (int) Math.ceil(p / 100.0 * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }

    @Override
    public void close() {
        socket.close();
    }
}
