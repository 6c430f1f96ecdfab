package touchline.testing;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A UDP link between a robot and the console on loopback that drops, duplicates and reorders
 * datagrams, for the reliable-stream acceptance tests. The robot sends to {@link #robotSide()};
 * the console sees the proxy's {@link #consoleSide()} address as the robot.
 */
public final class LossyUdpProxy implements AutoCloseable {

    private final DatagramSocket robotFacing;
    private final DatagramSocket consoleFacing;
    private final InetSocketAddress console;
    private final double drop, duplicate, reorder;
    private final Random random;
    private volatile SocketAddress robot;
    private final AtomicLong forwarded = new AtomicLong();
    private final AtomicLong impaired = new AtomicLong();
    private final Thread up, down;

    public LossyUdpProxy(InetSocketAddress console, double drop, double duplicate, double reorder, long seed) throws IOException {
        this.console = console;
        this.drop = drop;
        this.duplicate = duplicate;
        this.reorder = reorder;
        this.random = new Random(seed);
        robotFacing = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        consoleFacing = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        up = new Thread(() -> pump(robotFacing, consoleFacing, true), "proxy-up");
        down = new Thread(() -> pump(consoleFacing, robotFacing, false), "proxy-down");
        up.setDaemon(true);
        down.setDaemon(true);
        up.start();
        down.start();
    }

    public InetSocketAddress robotSide() {
        return (InetSocketAddress) robotFacing.getLocalSocketAddress();
    }

    public InetSocketAddress consoleSide() {
        return (InetSocketAddress) consoleFacing.getLocalSocketAddress();
    }

    public long forwarded() {
        return forwarded.get();
    }

    public long impaired() {
        return impaired.get();
    }

    private void pump(DatagramSocket from, DatagramSocket to, boolean fromRobot) {
        byte[] buf = new byte[2048];
        DatagramPacket held = null;
        while (!from.isClosed()) {
            try {
                DatagramPacket in = new DatagramPacket(buf, buf.length);
                from.receive(in);
                if (fromRobot) {
                    robot = in.getSocketAddress();
                }
                SocketAddress target = fromRobot ? console : robot;
                if (target == null) {
                    continue;
                }
                DatagramPacket out = new DatagramPacket(java.util.Arrays.copyOf(in.getData(), in.getLength()), in.getLength(), target);
                double r;
                synchronized (random) {
                    r = random.nextDouble();
                }
                if (r < drop) {
                    impaired.incrementAndGet();
                    continue;
                }
                if (held == null && r < drop + reorder) {
                    held = out; // goes out after the next one
                    impaired.incrementAndGet();
                    continue;
                }
                to.send(out);
                forwarded.incrementAndGet();
                if (r < drop + reorder + duplicate) {
                    to.send(out);
                    impaired.incrementAndGet();
                }
                if (held != null) {
                    to.send(held);
                    held = null;
                }
            } catch (IOException e) {
                return;
            }
        }
    }

    @Override
    public void close() {
        robotFacing.close();
        consoleFacing.close();
    }
}
