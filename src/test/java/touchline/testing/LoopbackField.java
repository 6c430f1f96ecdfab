package touchline.testing;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The field's network for one robot and several consoles on loopback (which has no
 * broadcast): what the robot sends reaches every console, what any console sends reaches the
 * robot. The robot is told to send to {@link #port()}.
 */
public final class LoopbackField implements AutoCloseable {

    private final DatagramChannel channel;
    private final List<InetSocketAddress> consoles = new CopyOnWriteArrayList<>();
    private final Thread thread;
    private volatile InetSocketAddress robot;

    public LoopbackField() throws IOException {
        channel = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
        thread = new Thread(this::run, "loopback-field");
        thread.setDaemon(true);
        thread.start();
    }

    public int port() throws IOException {
        return ((InetSocketAddress) channel.getLocalAddress()).getPort();
    }

    public void robotAt(int port) {
        robot = new InetSocketAddress("127.0.0.1", port);
    }

    public void console(int port) {
        consoles.add(new InetSocketAddress("127.0.0.1", port));
    }

    /** A console core started on a loopback port of its own and joined to the field. */
    public touchline.app.Console join() throws InterruptedException {
        touchline.app.Console c = new touchline.app.Console(touchline.app.ConsoleConfig.defaults()
                .withUdp(touchline.transport.UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
        console(c.field().port());
        return c;
    }

    public void forget(int consolePort) {
        consoles.remove(new InetSocketAddress("127.0.0.1", consolePort));
    }

    private void run() {
        ByteBuffer buf = ByteBuffer.allocate(65_536);
        try {
            while (channel.isOpen()) {
                buf.clear();
                SocketAddress from = channel.receive(buf);
                buf.flip();
                if (from.equals(robot)) {
                    for (InetSocketAddress c : consoles) {
                        channel.send(buf.duplicate(), c);
                    }
                } else if (robot != null) {
                    channel.send(buf, robot);
                }
            }
        } catch (IOException e) {
            // closed
        }
    }

    @Override
    public void close() throws Exception {
        channel.close();
        thread.join(5_000);
    }
}
