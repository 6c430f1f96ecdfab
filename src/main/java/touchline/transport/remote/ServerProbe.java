package touchline.transport.remote;

import org.json.JSONException;
import org.json.JSONObject;

import javax.net.ssl.SSLContext;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.time.Duration;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Asks a Foxglove WebSocket server once what it calls itself (its {@code serverInfo}'s name),
 * then hangs up: whether a URL on the command line is another Touchline (to be viewed) or a
 * robot's bridge. Empty when the server cannot be reached or says nothing within the wait.
 */
public final class ServerProbe {

    private final URI uri;
    private final SSLContext tls;
    private final Duration wait;

    public ServerProbe(URI uri, SSLContext tls, Duration wait) {
        this.uri = uri;
        this.tls = tls;
        this.wait = wait;
    }

    /** The server's name, or empty. Blocks up to the wait. */
    public Optional<String> serverName() throws InterruptedException {
        CompletableFuture<String> name = new CompletableFuture<>();
        HttpClient.Builder b = HttpClient.newBuilder().connectTimeout(wait);
        if (tls != null) {
            b.sslContext(tls);
        }
        WebSocket.Listener listener = new WebSocket.Listener() {
            private final StringBuilder text = new StringBuilder();

            @Override
            public CompletionStage<?> onText(WebSocket ws, CharSequence part, boolean last) {
                text.append(part);
                if (last) {
                    try {
                        JSONObject o = new JSONObject(text.toString());
                        name.complete("serverInfo".equals(o.optString("op")) ? o.optString("name", "") : "");
                    } catch (JSONException e) {
                        name.complete("");
                    }
                }
                ws.request(1);
                return null;
            }
        };
        CompletableFuture<WebSocket> socket = b.build().newWebSocketBuilder()
                .subprotocols(FoxgloveConnection.SUBPROTOCOLS[0], FoxgloveConnection.SUBPROTOCOLS[1]).connectTimeout(wait)
                .buildAsync(uri, listener);
        socket.whenComplete((ws, failure) -> {
            if (failure != null) {
                name.complete("");
            }
        });
        try {
            return Optional.of(name.get(wait.toMillis(), TimeUnit.MILLISECONDS)).filter(n -> !n.isEmpty());
        } catch (ExecutionException | TimeoutException e) {
            return Optional.empty();
        } finally {
            socket.thenAccept(WebSocket::abort);
            socket.exceptionally(e -> null);
        }
    }
}
