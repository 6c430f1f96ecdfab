package touchline.ui.viewers;

import javafx.scene.control.TableView;
import javafx.scene.control.TextField;
import javafx.scene.control.ToggleButton;
import javafx.scene.input.KeyCode;
import org.json.JSONObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.UiTest;
import touchline.ui.viewers.ViewersView;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.util.List;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ConsoleWindowFixture;

/**
 * The window serves itself to viewers: Ctrl+Shift+V switches serving on, the Viewers view shows
 * the URL, a real WebSocket client (the JDK's) connects with it and appears in the table with
 * its subscription; Ctrl+Shift+V again stops serving and the viewer is disconnected.
 */
@UiTest
@Tag("integration")
class ViewersUiTest {

    private ConsoleWindowFixture ui;

    private void shortcut() throws Exception {
        ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
        ui.robot.press(KeyCode.CONTROL, KeyCode.SHIFT, KeyCode.V).release(KeyCode.V, KeyCode.SHIFT, KeyCode.CONTROL);
    }

    @Test
    void theShortcutServesTheWindowAndAViewerShowsUpWithItsSubscription() throws Exception {
        ui.window.serving().setPort(0); // any free port: the user's default is 8765
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        ui.fxRun(() -> ui.window.open("viewers", ViewSource.NONE));
        ViewersView view = ui.view(ViewersView.class);
        assertNotNull(view);
        assertFalse(ui.window.serving().serving());

        shortcut();
        ui.await(30, () -> ((ToggleButton) view.node().lookup("#viewers-toggle")).isSelected());
        String url = ui.fx(() -> ((TextField) view.node().lookup("#viewers-url")).getText());
        assertTrue(url.matches("ws://127\\.0\\.0\\.1:\\d+/"), url);
        // switched by the shortcut, not the view's button: the view says so too (it said "Not serving." before)
        ui.await(30, () -> ((javafx.scene.control.Labeled) view.node().lookup("#viewers-status")).getText()
                .startsWith("Serving to viewers: ws://127.0.0.1:"));

        // a web page of another site open in this laptop's browser is turned away, and the view says so
        java.util.concurrent.ExecutionException refused = assertThrows(java.util.concurrent.ExecutionException.class,
                () -> HttpClient.newHttpClient().newWebSocketBuilder().header("Origin", "https://evil.example.com")
                        .subprotocols("foxglove.websocket.v1").buildAsync(URI.create(url), new WebSocket.Listener() { })
                        .get(10, TimeUnit.SECONDS));
        assertEquals(403, ((java.net.http.WebSocketHandshakeException) refused.getCause()).getResponse().statusCode());
        ui.await(30, () -> ((javafx.scene.control.Labeled) view.node().lookup("#viewers-status")).getText()
                .endsWith("refused 1 (web page not allowed 1)"));

        List<JSONObject> heard = new CopyOnWriteArrayList<>();
        boolean[] closed = {false}; // written by the client's thread, read by the test's: only ever set
        WebSocket ws = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols("foxglove.websocket.v1")
                .buildAsync(URI.create(url), new WebSocket.Listener() {
                    private final StringBuilder text = new StringBuilder();

                    @Override
                    public CompletionStage<?> onText(WebSocket w, CharSequence part, boolean last) {
                        text.append(part);
                        if (last) {
                            heard.add(new JSONObject(text.toString()));
                            text.setLength(0);
                        }
                        w.request(1);
                        return null;
                    }

                    @Override
                    public CompletionStage<?> onClose(WebSocket w, int code, String reason) {
                        closed[0] = true;
                        return null;
                    }

                    @Override
                    public void onError(WebSocket w, Throwable error) {
                        closed[0] = true; // the connection went without a close frame
                    }
                }).get(10, TimeUnit.SECONDS);
        touchline.testing.Await.until("the channels", () -> heard.stream().anyMatch(o -> o.optString("op").equals("advertise")));
        int matchMode = heard.stream().filter(o -> o.optString("op").equals("advertise"))
                .flatMap(o -> o.getJSONArray("channels").toList().stream()).map(c -> new JSONObject((java.util.Map<?, ?>) c))
                .filter(c -> c.getString("topic").equals("/touchline/matchMode")).findFirst().orElseThrow().getInt("id");
        ws.sendText(new JSONObject().put("op", "subscribe").put("subscriptions", new org.json.JSONArray()
                .put(new JSONObject().put("id", 1).put("channelId", matchMode))).toString(), true).get(10, TimeUnit.SECONDS);

        @SuppressWarnings("unchecked")
        TableView<ViewersView.Row> table = (TableView<ViewersView.Row>) ui.fx(() -> view.node().lookup("#viewers-table"));
        ui.await(30, () -> table.getItems().size() == 1 && table.getItems().get(0).subscriptions() == 1);
        ViewersView.Row row = ui.fx(() -> table.getItems().get(0));
        assertTrue(row.address().startsWith("127.0.0.1:"), row.address());
        assertEquals("/touchline/matchMode", row.topics());

        shortcut();
        ui.await(30, () -> !((ToggleButton) view.node().lookup("#viewers-toggle")).isSelected());
        assertFalse(ui.window.serving().serving());
        touchline.testing.Await.until("the viewer is disconnected", () -> closed[0] || ws.isInputClosed());
        ui.await(30, () -> table.getItems().isEmpty());
    }
}
