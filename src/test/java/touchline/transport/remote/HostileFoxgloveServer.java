package touchline.transport.remote;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Base64;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A real WebSocket server on loopback, written on the JDK's plain sockets so that it can speak
 * {@code foxglove.websocket.v1} as badly as a test wants: each connection runs the next of the
 * given scripts (the last one again for every further connection), which writes frames, bytes
 * or nothing at all. What the client sends (its subscriptions) is kept for the test to read.
 */
final class HostileFoxgloveServer implements AutoCloseable {

    /** What the server does on one connection. */
    @FunctionalInterface
    interface Script {
        void run(Connection c) throws IOException, InterruptedException;
    }

    private final ServerSocket listening;
    private final List<Script> scripts;
    private final AtomicInteger connections = new AtomicInteger();
    private final List<Socket> open = new CopyOnWriteArrayList<>();
    private final List<String> fromClients = new CopyOnWriteArrayList<>();
    private final Thread acceptor;

    HostileFoxgloveServer(Script... scripts) throws IOException {
        this.scripts = List.of(scripts);
        this.listening = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        this.acceptor = new Thread(this::accept, "hostile-server");
        acceptor.setDaemon(true);
        acceptor.start();
    }

    String url() {
        return "ws://127.0.0.1:" + listening.getLocalPort() + "/";
    }

    int connections() {
        return connections.get();
    }

    /** Every text message the clients sent, in order. */
    List<String> fromClients() {
        return fromClients;
    }

    private void accept() {
        while (!listening.isClosed()) {
            try {
                Socket s = listening.accept();
                open.add(s);
                int n = connections.getAndIncrement();
                Script script = scripts.get(Math.min(n, scripts.size() - 1));
                Thread t = new Thread(() -> {
                    try (s) {
                        script.run(new Connection(s));
                    } catch (IOException | InterruptedException e) {
                        // the client went away, or the test ended
                    }
                }, "hostile-connection-" + n);
                t.setDaemon(true);
                t.start();
            } catch (IOException closed) {
                return;
            }
        }
    }

    @Override
    public void close() throws IOException {
        listening.close();
        for (Socket s : open) {
            s.close();
        }
    }

    /** One accepted connection, raw: the handshake, frames, bytes. */
    final class Connection {

        private final Socket socket;
        private final InputStream in;
        private final OutputStream out;

        Connection(Socket socket) throws IOException {
            this.socket = socket;
            this.in = socket.getInputStream();
            this.out = socket.getOutputStream();
        }

        /** Reads the HTTP upgrade request and accepts it with the Foxglove subprotocol. */
        void handshake() throws IOException {
            String key = null;
            for (String line = line(); !line.isEmpty(); line = line()) {
                int colon = line.indexOf(':');
                if (colon > 0 && line.substring(0, colon).trim().toLowerCase(Locale.ROOT).equals("sec-websocket-key")) {
                    key = line.substring(colon + 1).trim();
                }
            }
            if (key == null) {
                throw new IOException("not a WebSocket upgrade");
            }
            raw(("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                    + "Sec-WebSocket-Accept: " + accept(key) + "\r\nSec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n")
                    .getBytes(StandardCharsets.US_ASCII));
        }

        private String line() throws IOException {
            ByteArrayOutputStream b = new ByteArrayOutputStream();
            for (int c = in.read(); c != '\n'; c = in.read()) {
                if (c < 0) {
                    throw new IOException("closed during the handshake");
                }
                if (c != '\r') {
                    b.write(c);
                }
            }
            return b.toString(StandardCharsets.US_ASCII);
        }

        private static String accept(String key) {
            try {
                byte[] sha = MessageDigest.getInstance("SHA-1").digest(
                        (key + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11").getBytes(StandardCharsets.US_ASCII));
                return Base64.getEncoder().encodeToString(sha);
            } catch (NoSuchAlgorithmException e) {
                throw new IllegalStateException(e);
            }
        }

        void serverInfo() throws IOException {
            text("{\"op\":\"serverInfo\",\"name\":\"hostile\",\"capabilities\":[\"time\"],\"supportedEncodings\":[]}");
        }

        void text(String s) throws IOException {
            frame(true, 0x1, s.getBytes(StandardCharsets.UTF_8));
        }

        void binary(byte[] b) throws IOException {
            frame(true, 0x2, b);
        }

        /** A message data op: channel (subscription) id, log time, payload. */
        void message(int channel, long timeNanos, byte[] payload) throws IOException {
            binary(messageData(channel, timeNanos, payload));
        }

        /** A frame header with its payload as given, which may be shorter than {@code declared}. */
        void frame(boolean fin, int opcode, byte[] payload, long declared) throws IOException {
            ByteArrayOutputStream h = new ByteArrayOutputStream();
            h.write((fin ? 0x80 : 0) | opcode);
            if (declared < 126) {
                h.write((int) declared);
            } else if (declared < 65536) {
                h.write(126);
                h.write((int) (declared >> 8));
                h.write((int) declared & 0xFF);
            } else {
                h.write(127);
                h.writeBytes(ByteBuffer.allocate(8).putLong(declared).array());
            }
            h.writeBytes(payload);
            raw(h.toByteArray());
        }

        void frame(boolean fin, int opcode, byte[] payload) throws IOException {
            frame(fin, opcode, payload, payload.length);
        }

        void raw(byte[] bytes) throws IOException {
            out.write(bytes);
            out.flush();
        }

        /** The client's next text message (its pings and pongs skipped); kept in {@link #fromClients()}. */
        String readText() throws IOException {
            while (true) {
                int b0 = in.read();
                int b1 = in.read();
                if (b0 < 0 || b1 < 0) {
                    throw new IOException("the client closed");
                }
                long n = b1 & 0x7F;
                if (n == 126) {
                    n = (in.read() << 8) | in.read();
                } else if (n == 127) {
                    n = ByteBuffer.wrap(in.readNBytes(8)).getLong();
                }
                byte[] mask = (b1 & 0x80) != 0 ? in.readNBytes(4) : new byte[4];
                byte[] payload = in.readNBytes((int) n);
                for (int i = 0; i < payload.length; i++) {
                    payload[i] ^= mask[i % 4];
                }
                int opcode = b0 & 0x0F;
                if (opcode == 0x8) {
                    throw new IOException("the client closed");
                }
                if (opcode == 0x1) {
                    String s = new String(payload, StandardCharsets.UTF_8);
                    fromClients.add(s);
                    return s;
                }
            }
        }

        /** Reads (and keeps) what the client sends until it or the test closes the connection. */
        void hold() throws IOException {
            while (!socket.isClosed()) {
                readText();
            }
        }

        /** Holds the connection, reading what comes and answering nothing, until the client or the test closes it. */
        void ignore() throws IOException {
            while (in.read() >= 0) {
                // swallowed
            }
        }

        void closeNow() throws IOException {
            socket.close();
        }
    }

    static byte[] messageData(int channel, long timeNanos, byte[] payload) {
        return ByteBuffer.allocate(13 + payload.length).order(ByteOrder.LITTLE_ENDIAN)
                .put((byte) 0x01).putInt(channel).putLong(timeNanos).put(payload).array();
    }
}
