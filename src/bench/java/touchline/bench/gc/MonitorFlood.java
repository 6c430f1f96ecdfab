package touchline.bench.gc;

import touchline.protocol.gamecontroller.MonitorRequest;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.concurrent.locks.LockSupport;

/**
 * Monitor requests ("RGTr") at a steady rate, each from a loopback host that never asked before
 * (127.1.0.1 upwards through 127.0.0.0/8, a socket bound to it for the one request): what a
 * flood of new registrations looks like to the GameController. Sends in batches every 10 ms
 * from its own thread until closed; counts what it sent.
 */
final class MonitorFlood implements AutoCloseable {

    private static final long BATCH_NANOS = 10_000_000;
    /** 127.1.0.1: the first host (127.0.0.x is left to the probe and the GameController). */
    private static final int FIRST_HOST = (127 << 24) | (1 << 16) | 1;

    private final InetSocketAddress target;
    private final int perSecond;
    private final Thread thread;
    private volatile boolean running = true;
    private int nextHost = FIRST_HOST;
    private long sent;
    private String failure = "";

    /**
     * @param target    the GameController's monitor-request address
     * @param perSecond requests a second, each from a new host
     */
    MonitorFlood(InetSocketAddress target, int perSecond) {
        this.target = target;
        this.perSecond = perSecond;
        thread = new Thread(this::loop, "monitor-flood");
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    private void loop() {
        byte[] request = new MonitorRequest().encode();
        long next = System.nanoTime();
        double owed = 0;
        while (running) {
            owed += perSecond * (BATCH_NANOS / 1e9);
            for (; owed >= 1; owed--) {
                try (DatagramChannel c = DatagramChannel.open()) {
                    c.bind(new InetSocketAddress(host(), 0));
                    c.send(ByteBuffer.wrap(request), target);
                    sent++;
                } catch (IOException e) {
                    failure = e.toString();
                    return;
                }
            }
            next += BATCH_NANOS;
            LockSupport.parkNanos(next - System.nanoTime());
        }
    }

    /** The next host's address, skipping .0 and .255 in the last byte. */
    private InetAddress host() throws IOException {
        int h = nextHost++;
        if ((h & 0xFF) == 255) {
            nextHost += 2;
        }
        return InetAddress.getByAddress(new byte[]{(byte) (h >>> 24), (byte) (h >>> 16), (byte) (h >>> 8), (byte) h});
    }

    /** Requests sent so far, and why the flood stopped early ("" when it did not); read after {@link #close}. */
    String summary() {
        return sent + " requests from as many hosts" + (failure.isEmpty() ? "" : "; stopped early: " + failure);
    }

    @Override
    public void close() {
        running = false;
        try {
            thread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
