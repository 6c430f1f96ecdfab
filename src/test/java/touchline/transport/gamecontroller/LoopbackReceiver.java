package touchline.transport.gamecontroller;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.util.Arrays;

/** A plain UDP socket on 127.0.0.1 with an OS-chosen port, standing in for a robot. */
final class LoopbackReceiver implements AutoCloseable {

    /** One received datagram with its receive time. */
    record Received(byte[] data, long nanos, InetSocketAddress from) {
    }

    final DatagramSocket socket;

    LoopbackReceiver() throws IOException {
        socket = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
    }

    InetSocketAddress address() {
        return (InetSocketAddress) socket.getLocalSocketAddress();
    }

    Received receive(int timeoutMs) throws IOException {
        socket.setSoTimeout(timeoutMs);
        byte[] buf = new byte[2048];
        DatagramPacket p = new DatagramPacket(buf, buf.length);
        try {
            socket.receive(p);
        } catch (SocketTimeoutException e) {
            return null;
        }
        return new Received(Arrays.copyOf(buf, p.getLength()), System.nanoTime(),
                (InetSocketAddress) p.getSocketAddress());
    }

    void send(byte[] data, InetSocketAddress to) throws IOException {
        socket.send(new DatagramPacket(data, data.length, to));
    }

    @Override
    public void close() {
        socket.close();
    }
}
