package touchline.serve;

import org.junit.jupiter.api.Test;
import touchline.testing.Await;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.net.http.WebSocketHandshakeException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Who gets a connection at all (issue 35): web pages by their origin, and connections that take
 * their time over the upgrade or come in numbers. Real WebSocket clients and raw sockets on
 * loopback.
 */
class FoxgloveAdmissionTest {

    /** The HTTP status of an upgrade sent with {@code origin} (null: none), 101 when it was accepted. */
    private static int upgrade(int port, String origin) throws Exception {
        WebSocket.Builder b = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols("foxglove.websocket.v1");
        if (origin != null) {
            b.header("Origin", origin);
        }
        try {
            b.buildAsync(URI.create("ws://127.0.0.1:" + port + "/"), new WebSocket.Listener() { })
                    .get(30, TimeUnit.SECONDS).abort();
            return 101;
        } catch (ExecutionException e) {
            if (e.getCause() instanceof WebSocketHandshakeException h) {
                return h.getResponse().statusCode();
            }
            throw e;
        }
    }

    @Test
    void aWebPageOfAnotherOriginIsRefusedAndCountedToolsAndKnownViewersAreServed() throws Exception {
        ServeConfig config = ServeConfig.defaults().withPort(0)
                .withOrigins(new AllowedOrigins(List.of("https://viewer.example.org/")));
        try (ServedField field = new ServedField(config)) {
            int port = field.server().port();
            assertEquals(403, upgrade(port, "https://evil.example.com"), "any page open in the laptop's browser");
            assertEquals(403, upgrade(port, "null"), "a sandboxed frame of any page");
            assertEquals(403, upgrade(port, "http://127.0.0.1:8080"), "a page served from this machine");
            assertEquals(101, upgrade(port, null), "a tool sends no origin");
            assertEquals(101, upgrade(port, "https://app.foxglove.dev"));
            assertEquals(101, upgrade(port, "https://lichtblick-suite.github.io"));
            assertEquals(101, upgrade(port, "https://Viewer.Example.org"), "added with --allow-origin");
            assertEquals(3, field.server().stats().refused());
            assertEquals(Map.of("web page not allowed", 3L), field.server().stats().refusedBy());
            assertEquals("refused 3 (web page not allowed 3)", field.server().stats().refusedInWords(), "the status line");
        }
    }

    /**
     * 40 connections trickle their upgrade request a byte every 100 ms, each byte well within any
     * read timeout (the old 10 s read timeout kept them open for ever): at most 8 wait at once (the oldest gives way to a new one), the last ones
     * are closed at the deadline counted from accept, and a real viewer connects meanwhile.
     */
    @Test
    void tricklingConnectionsAreCappedAndClosedAtTheDeadlineWhileAViewerConnects() throws Exception {
        ServeConfig config = ServeConfig.defaults().withPort(0).withLimits(new ConnectionLimits(200, 8, 3000));
        ScheduledExecutorService trickle = Executors.newSingleThreadScheduledExecutor();
        List<Socket> slow = new ArrayList<>();
        try (ServedField field = new ServedField(config)) {
            int port = field.server().port();
            // an upgrade request whose last header never ends
            byte[] request = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nX-Pad: "
                    .getBytes(StandardCharsets.US_ASCII);
            for (int i = 0; i < 40; i++) {
                Socket s = new Socket();
                s.connect(new InetSocketAddress("127.0.0.1", port), 30_000);
                s.setSoTimeout(60_000);
                slow.add(s);
                int[] next = {0};
                trickle.scheduleAtFixedRate(() -> {
                    try {
                        s.getOutputStream().write(next[0] < request.length ? request[next[0]++] : 'a');
                    } catch (IOException closedByTheServer) {
                        // what the test waits for
                    }
                }, 0, 100, TimeUnit.MILLISECONDS);
            }
            Await.until("40 accepted, 8 of them waiting", () -> field.server().stats().refusedBy()
                    .getOrDefault("upgrade slots full", 0L) == 32 && field.server().stats().upgrading() == 8);

            try (FoxgloveTestClient viewer = new FoxgloveTestClient(port)) {
                assertEquals("serverInfo", viewer.serverInfo().getString("op"), "a real viewer gets in meanwhile");
                Await.until("every trickling connection closed", () -> field.server().stats().upgrading() == 0);
                Map<String, Long> by = field.server().stats().refusedBy();
                assertEquals(40L, by.getOrDefault("upgrade slots full", 0L) + by.getOrDefault("upgrade deadline", 0L), by.toString());
                assertTrue(by.getOrDefault("upgrade deadline", 0L) >= 1, by.toString());
                for (Socket s : slow) {
                    assertTrue(closedByServer(s), "closed by the server");
                }
                assertEquals(1, field.server().stats().viewers());
                assertFalse(viewer.closed());
            }
        } finally {
            trickle.shutdownNow();
            for (Socket s : slow) {
                s.close();
            }
        }
    }

    private static boolean closedByServer(Socket s) throws IOException {
        InputStream in = s.getInputStream();
        try {
            return in.read() == -1;
        } catch (java.net.SocketException reset) {
            return true; // closed while our bytes were still arriving: a reset
        }
    }

    @Test
    void oneConnectionOverTheCapIsClosedAtOnceAndCounted() throws Exception {
        ServeConfig config = ServeConfig.defaults().withPort(0).withLimits(new ConnectionLimits(2, 8, 10_000));
        try (ServedField field = new ServedField(config);
             FoxgloveTestClient first = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient second = new FoxgloveTestClient(field.server().port());
             Socket third = new Socket()) {
            first.serverInfo();
            second.serverInfo();
            third.connect(new InetSocketAddress("127.0.0.1", field.server().port()), 30_000);
            third.setSoTimeout(60_000);
            OutputStream ignored = third.getOutputStream();
            assertTrue(closedByServer(third));
            assertEquals(Map.of("too many connections", 1L), field.server().stats().refusedBy());
            assertEquals(2, field.server().stats().viewers());
        }
    }

    /**
     * An allowed web page (Foxglove's web app open in this laptop's browser) connects from loopback
     * like a tool, but switches no option: whatever page that app is made to open would switch the
     * team's robots. A tool (no origin) on the same server is served.
     */
    @Test
    void anAllowedWebPageWatchesButSwitchesNoOption() throws Exception {
        try (ServedField field = new ServedField()) {
            List<String> asked = new java.util.concurrent.CopyOnWriteArrayList<>();
            field.server().offerOptionSwitches((robot, option, on) -> {
                asked.add(robot + " " + option + " " + on);
                return touchline.transport.SendResult.sent();
            });
            List<String> texts = new java.util.concurrent.CopyOnWriteArrayList<>();
            WebSocket page = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols("foxglove.websocket.v1")
                    .header("Origin", "https://app.foxglove.dev")
                    .buildAsync(URI.create("ws://127.0.0.1:" + field.server().port() + "/"), new WebSocket.Listener() {
                        @Override
                        public java.util.concurrent.CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
                            texts.add(data.toString());
                            ws.request(1);
                            return null;
                        }
                    }).get(30, TimeUnit.SECONDS);
            page.sendText("{\"op\":\"switchOption\",\"robot\":3,\"option\":\"demo.text\",\"on\":true,\"id\":\"p\"}", true);
            Await.until("the page's answer", () -> texts.stream().anyMatch(t -> t.contains("\"id\":\"p\"")));
            String answer = texts.stream().filter(t -> t.contains("\"id\":\"p\"")).findFirst().orElseThrow();
            assertTrue(answer.contains("web page"), answer);
            assertEquals(List.of(), asked, "a web page switched an option");
            page.abort();
            try (FoxgloveTestClient tool = new FoxgloveTestClient(field.server().port())) {
                tool.send("{\"op\":\"switchOption\",\"robot\":3,\"option\":\"demo.text\",\"on\":true,\"id\":\"t\"}");
                Await.until("the tool's switch", () -> asked.size() == 1);
            }
        }
    }
}
