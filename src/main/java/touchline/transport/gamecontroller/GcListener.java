package touchline.transport.gamecontroller;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.DatagramChannel;
import java.util.Arrays;

/**
 * A UDP socket with its own thread that hands every datagram to a handler: used for return
 * packets (3939, or 3838 in the 2014 profile) and for hearing other GameControllers on 3838.
 * Binds with SO_REUSEADDR so robot stubs or monitors can share the port (when made, so a port in
 * use fails at once); its thread starts with {@link #start()}, which its owner calls. A failing
 * handler is logged and the next datagram is still delivered.
 */
public final class GcListener implements AutoCloseable {

    /** Receives one datagram (called on the listener's thread). */
    @FunctionalInterface
    public interface Handler {
        void onDatagram(byte[] data, InetSocketAddress from);
    }

    private static final Logger LOG = LoggerFactory.getLogger(GcListener.class);

    private final DatagramChannel channel;
    private final Handler handler;
    private final int maxDatagram;
    private final Thread thread;
    private volatile boolean running = true;

    public GcListener(InetSocketAddress bind, Handler handler, String name) throws IOException {
        this(bind, handler, name, 2048);
    }

    /** @param maxDatagram the largest datagram received whole (a larger one arrives cut to this size) */
    public GcListener(InetSocketAddress bind, Handler handler, String name, int maxDatagram) throws IOException {
        this.handler = handler;
        this.maxDatagram = maxDatagram;
        this.channel = DatagramChannel.open();
        channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
        channel.bind(bind);
        thread = new Thread(this::loop, name);
        thread.setDaemon(true);
    }

    /** Starts the thread that receives; datagrams that arrived since the socket was bound wait in it. */
    public GcListener start() {
        synchronized (thread) {
            if (thread.getState() == Thread.State.NEW && running) {
                thread.start();
            }
        }
        return this;
    }

    public InetSocketAddress localAddress() throws IOException {
        return (InetSocketAddress) channel.getLocalAddress();
    }

    private void loop() {
        ByteBuffer buf = ByteBuffer.allocate(maxDatagram);
        while (running) {
            try {
                buf.clear();
                InetSocketAddress from = (InetSocketAddress) channel.receive(buf);
                buf.flip();
                byte[] data = Arrays.copyOf(buf.array(), buf.limit());
                try {
                    handler.onDatagram(data, from);
                } catch (RuntimeException e) {
                    LOG.error("GameController datagram handler failed on {} bytes from {}", data.length, from, e);
                }
            } catch (ClosedChannelException e) {
                return;
            } catch (IOException e) {
                if (running) {
                    LOG.warn("GameController listener: {}", e.toString());
                }
            }
        }
    }

    @Override
    public void close() {
        running = false;
        try {
            channel.close();
            thread.join(2000);
        } catch (IOException ignored) {
            // nothing to flush on a datagram socket
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
