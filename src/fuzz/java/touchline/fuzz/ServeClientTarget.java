package touchline.fuzz;

import touchline.app.SystemClock;
import touchline.bench.record.SyntheticTeam;
import touchline.protocol.MessageKinds;
import touchline.serve.FoxgloveServer;
import touchline.serve.ServeConfig;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

/**
 * A viewer's message to the live server ({@code serve}, the Foxglove WebSocket protocol): the
 * input is sent as one frame — text when its first byte is even (the rest as UTF-8), binary
 * when odd (the rest) — to a {@link FoxgloveServer} on 127.0.0.1 serving a team's traffic,
 * and then a WebSocket ping. The server handles a connection's frames in order, so its pong
 * says the frame was dealt with; no pong within 5 s on an open connection is a finding (a
 * server that stalls on a message). A server that closes the connection has refused the
 * frame: the next input opens a new one. The server is started by {@link #prepare} or the
 * first input.
 */
final class ServeClientTarget implements FuzzTarget {

    private static final long PONG_SECONDS = 5;

    private FoxgloveServer server;
    private HttpClient http;
    private Viewer viewer;

    /** One connection: counts the pongs and whether the server closed it. */
    private static final class Viewer implements WebSocket.Listener {
        final Semaphore pongs = new Semaphore(0);
        volatile boolean closed;
        WebSocket socket;

        @Override
        public void onOpen(WebSocket webSocket) {
            webSocket.request(Long.MAX_VALUE);
        }

        @Override
        public CompletionStage<?> onPong(WebSocket webSocket, ByteBuffer message) {
            pongs.release();
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
            closed = true;
            pongs.release();
            return null;
        }

        @Override
        public void onError(WebSocket webSocket, Throwable error) {
            closed = true;
            pongs.release();
        }
    }

    @Override
    public String name() {
        return "serve-client";
    }

    @Override
    public void accept(byte[] input) {
        try {
            Viewer v = connected();
            boolean text = input.length == 0 || (input[0] & 1) == 0;
            byte[] rest = input.length == 0 ? input : java.util.Arrays.copyOfRange(input, 1, input.length);
            try {
                if (text) {
                    v.socket.sendText(new String(rest, StandardCharsets.UTF_8), true).get(PONG_SECONDS, TimeUnit.SECONDS);
                } else {
                    v.socket.sendBinary(ByteBuffer.wrap(rest), true).get(PONG_SECONDS, TimeUnit.SECONDS);
                }
                v.socket.sendPing(ByteBuffer.allocate(0)).get(PONG_SECONDS, TimeUnit.SECONDS);
            } catch (java.util.concurrent.ExecutionException closedMeanwhile) {
                viewer = null; // the server closed the connection: its answer to this frame
                return;
            }
            boolean answered = v.pongs.tryAcquire(PONG_SECONDS, TimeUnit.SECONDS);
            if (v.closed) {
                viewer = null;
                return;
            }
            FuzzTarget.check(answered, "the server did not answer a ping within " + PONG_SECONDS
                    + " s after a viewer's frame of " + input.length + " bytes");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        } catch (java.util.concurrent.TimeoutException e) {
            throw new AssertionError("the server did not take a viewer's frame within " + PONG_SECONDS + " s", e);
        }
    }

    /** Starts the server and sends the first frames (loading and instrumenting the server's code takes seconds). */
    @Override
    public void prepare() {
        for (byte[] seed : seeds()) {
            accept(seed);
        }
    }

    private Viewer connected() throws InterruptedException {
        if (server == null) {
            server = new FoxgloveServer(ServeConfig.defaults().withPort(0), new MessageKinds(), new SystemClock()).start();
            new SyntheticTeam(3, 1_760_000_000_000_000L, 42).generate(1, server::accept); // channels to subscribe to
            http = HttpClient.newHttpClient();
        }
        if (viewer == null) {
            Viewer v = new Viewer();
            try {
                v.socket = http.newWebSocketBuilder().subprotocols("foxglove.websocket.v1")
                        .buildAsync(URI.create("ws://127.0.0.1:" + server.port() + "/"), v)
                        .get(PONG_SECONDS, TimeUnit.SECONDS);
            } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
                throw new AssertionError("a new viewer cannot connect to the server", e);
            }
            viewer = v;
        }
        return viewer;
    }

    @Override
    public void close() {
        if (viewer != null && !viewer.closed) {
            viewer.socket.abort();
        }
        viewer = null;
        if (server != null) {
            server.close();
            server = null;
        }
    }

    /** The client operations of the protocol, good and bad, as text; a client message as binary. */
    @Override
    public List<byte[]> seeds() {
        List<String> ops = List.of(
                "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":1},{\"id\":2,\"channelId\":2}]}",
                "{\"op\":\"unsubscribe\",\"subscriptionIds\":[1,2,42]}",
                "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":-1,\"channelId\":99999}]}",
                "{\"op\":\"advertise\",\"channels\":[{\"id\":1,\"topic\":\"/cmd\",\"encoding\":\"json\",\"schemaName\":\"x\"}]}",
                "{\"op\":\"unadvertise\",\"channelIds\":[1]}",
                "{\"op\":\"getParameters\",\"parameterNames\":[\"a\"],\"id\":\"r\"}",
                "{\"op\":\"setParameters\",\"parameters\":[{\"name\":\"kick\",\"value\":1}]}",
                "{\"op\":\"subscribeConnectionGraph\"}",
                "{\"op\":\"fetchAsset\",\"uri\":\"package://x\",\"requestId\":1}",
                "{\"op\":\"fly\"}",
                "[1, 2, 3]");
        List<byte[]> seeds = new ArrayList<>();
        for (String op : ops) {
            byte[] b = op.getBytes(StandardCharsets.UTF_8);
            byte[] seed = new byte[b.length + 1];
            System.arraycopy(b, 0, seed, 1, b.length);
            seeds.add(seed); // first byte 0: a text frame
        }
        seeds.add(new byte[]{1, 1, 1, 0, 0, 0, 'k', 'i', 'c', 'k'}); // a binary client message on channel 1
        return seeds;
    }
}
