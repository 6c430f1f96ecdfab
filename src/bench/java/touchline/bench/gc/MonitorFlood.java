package touchline.bench.gc;

import touchline.protocol.gamecontroller.MonitorRequest;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * Monitor requests ("RGTr") at a steady rate from many loopback hosts (127.1.x.y, every one
 * its own address, so every request is a newcomer or a renewal as a flood from a subnet
 * would be): the load of {@code bench gc --monitor-flood N}. Sends in batches every 10 ms
 * from its own thread until closed; counts what it sent.
 */
final class MonitorFlood implements AutoCloseable {

    private static final long BATCH_NANOS = 10_000_000;

    private final List<DatagramChannel> hosts = new ArrayList<>();
    private final InetSocketAddress target;
    private final int perSecond;
    private final Thread thread;
    private volatile boolean running = true;
    private long sent;

    /**
     * @param target    the GameController's monitor-request address
     * @param perSecond requests a second
     * @param hostCount distinct source hosts, 127.1.0.1 upwards (at most 65 000)
     */
    MonitorFlood(InetSocketAddress target, int perSecond, int hostCount) throws IOException {
        this.target = target;
        this.perSecond = perSecond;
        for (int i = 1; i <= hostCount; i++) {
            DatagramChannel c = DatagramChannel.open();
            c.bind(new InetSocketAddress(InetAddress.getByAddress(new byte[]{127, 1, (byte) (i >> 8), (byte) i}), 0));
            hosts.add(c);
        }
        thread = new Thread(this::loop, "monitor-flood");
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    private void loop() {
        byte[] request = new MonitorRequest().encode();
        long next = System.nanoTime();
        int host = 0;
        double owed = 0;
        while (running) {
            owed += perSecond * (BATCH_NANOS / 1e9);
            for (; owed >= 1; owed--) {
                try {
                    hosts.get(host).send(ByteBuffer.wrap(request), target);
                    sent++;
                } catch (IOException e) {
                    return;
                }
                host = (host + 1) % hosts.size();
            }
            next += BATCH_NANOS;
            LockSupport.parkNanos(next - System.nanoTime());
        }
    }

    /** Requests sent so far (read after {@link #close}). */
    long sent() {
        return sent;
    }

    @Override
    public void close() {
        running = false;
        try {
            thread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        for (DatagramChannel c : hosts) {
            try {
                c.close();
            } catch (IOException ignored) {
                // a bench socket: nothing to flush
            }
        }
    }
}
