package touchline.ui.viewers;

import javafx.collections.FXCollections;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.CheckBox;
import javafx.scene.control.Label;
import javafx.scene.control.TableView;
import javafx.scene.control.TextField;
import javafx.scene.control.ToggleButton;
import javafx.scene.control.Tooltip;
import javafx.scene.input.ClipboardContent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.VBox;
import touchline.serve.FoxgloveServer;
import touchline.serve.ViewerInfo;
import touchline.ui.frame.FrameContext;
import touchline.ui.viewers.ServeToggle;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import touchline.ui.render.TextColumns;

/**
 * Serving this console to remote viewers (Foxglove, Lichtblick, another Touchline): the switch
 * (also View → Serve to viewers, Ctrl+Shift+V), the URL with its token to copy, and every viewer
 * connected with its subscriptions, its rate and what was dropped for it. Pulls twice a second.
 */
public final class ViewersView implements View {

    /** One viewer as the table shows it. */
    public record Row(String address, int subscriptions, String topics, double perSecond, long dropped) { }

    private final ServeToggle toggle;
    private final ToggleButton serve = new ToggleButton("Serve to viewers");
    private final TextField port = new TextField();
    private final CheckBox beyond = new CheckBox("Other machines may watch (with a token)");
    private final TextField url = new TextField();
    private final Button copy = new Button("Copy URL");
    private final Label status = new Label();
    private final TableView<Row> table = new TableView<>();
    private final BorderPane root = new BorderPane();
    private final Map<String, long[]> lastSent = new HashMap<>(); // address -> {sent, micros}

    private final touchline.transport.MicrosClock clock;

    public ViewersView(ViewContext context) {
        this.toggle = context.serving();
        this.clock = context.field().clock();
        serve.setId("viewers-toggle");
        port.setId("viewers-port");
        port.setPrefColumnCount(6);
        port.setText(Integer.toString(toggle.port()));
        port.setTooltip(new Tooltip("WebSocket port (0: any free one)"));
        beyond.setId("viewers-beyond");
        beyond.setSelected(toggle.beyondThisMachine());
        url.setId("viewers-url");
        url.setEditable(false);
        url.setPromptText("not serving");
        HBox.setHgrow(url, Priority.ALWAYS);
        copy.setId("viewers-copy");
        copy.setOnAction(e -> {
            ClipboardContent c = new ClipboardContent();
            c.putString(url.getText());
            javafx.scene.input.Clipboard.getSystemClipboard().setContent(c);
            status.setText("URL copied");
        });
        status.setId("viewers-status");
        serve.setOnAction(e -> flip());
        beyond.setOnAction(e -> toggle.setBeyondThisMachine(beyond.isSelected()));
        table.setId("viewers-table");
        table.setPlaceholder(new Label("No viewer connected"));
        // never narrower than their headers: in a narrow pane the table scrolls sideways
        TextColumns<Row> columns = new TextColumns<>(false);
        table.getColumns().add(columns.column("Viewer", Row::address, 150, "127.0.0.1:65535"));
        table.getColumns().add(columns.column("Subscriptions", r -> Integer.toString(r.subscriptions()), 0, ""));
        table.getColumns().add(columns.column("Messages/s", r -> String.format("%.0f", r.perSecond()), 0, ""));
        table.getColumns().add(columns.column("Dropped", r -> Long.toString(r.dropped()), 0, ""));
        table.getColumns().add(columns.column("Topics", Row::topics, 300, ""));
        Label portName = new Label("Port");
        HBox controls = new HBox(8, serve, portName, port, beyond);
        controls.setStyle("-fx-alignment: center-left;");
        HBox link = new HBox(8, url, copy);
        // a narrow pane (the demo layout's left one) scrolls sideways rather than cutting these to "…"
        for (javafx.scene.layout.Region r : List.of(serve, portName, port, beyond, copy)) {
            r.setMinWidth(javafx.scene.layout.Region.USE_PREF_SIZE);
        }
        url.setMinWidth(160);
        VBox top = new VBox(6, controls, link, status);
        top.setStyle("-fx-padding: 6 8 6 8;");
        root.setTop(top);
        root.setCenter(table);
    }

    /** The switch: takes the port and reach from the fields, then starts or stops. */
    private void flip() {
        if (!toggle.serving()) {
            try {
                toggle.setPort(Integer.parseInt(port.getText().strip()));
            } catch (NumberFormatException e) {
                status.setText("Port: a number, 0 for any free one");
                serve.setSelected(false);
                return;
            }
            toggle.setBeyondThisMachine(beyond.isSelected());
        }
        status.setText(toggle.toggle());
        show();
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        // twice a second (the pulse runs when the viewers change, see ConsoleChanges), at once when switched
        if (frame.nowMicros() - shownMicros >= 500_000 || serve.isSelected() != toggle.serving()) {
            shownMicros = frame.nowMicros();
            show();
        }
    }

    private String saidShown = "";
    private long shownMicros = Long.MIN_VALUE / 2;

    private void show() {
        boolean on = toggle.serving();
        serve.setSelected(on);
        port.setDisable(on);
        beyond.setDisable(on);
        Optional<FoxgloveServer> server = toggle.server();
        String shown = server.map(s -> String.join("  ", s.urls())).orElse("");
        if (!url.getText().equals(shown)) {
            url.setText(shown);
        }
        // what the toggle said last, however it was switched (button, menu, Ctrl+Shift+V), and who was turned away
        String said = toggle.said() + server.map(FoxgloveServer::stats).filter(st -> st.refused() > 0)
                .map(st -> "  ·  " + st.refusedInWords()).orElse("");
        if (!said.equals(saidShown)) {
            status.setText(said);
            saidShown = said;
        }
        table.getItems().setAll(rows(server.map(FoxgloveServer::viewers).orElse(List.of()), clock.nowMicros()));
    }

    private List<Row> rows(List<ViewerInfo> viewers, long nowMicros) {
        Map<String, long[]> next = new HashMap<>();
        List<Row> rows = FXCollections.observableArrayList();
        for (ViewerInfo v : viewers) {
            long[] before = lastSent.get(v.address());
            double rate = before == null || nowMicros <= before[1] ? 0 : (v.sent() - before[0]) * 1e6 / (nowMicros - before[1]);
            rows.add(new Row(v.address(), v.topics().size(), String.join(", ", v.topics()), rate, v.dropped()));
            next.put(v.address(), new long[]{v.sent(), nowMicros});
        }
        lastSent.clear();
        lastSent.putAll(next);
        return rows;
    }
}
