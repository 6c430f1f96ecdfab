package touchline.ui.consoles;

import javafx.geometry.Orientation;
import javafx.scene.Node;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.SplitPane;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableView;
import javafx.scene.control.TextArea;
import javafx.scene.control.TextField;
import javafx.scene.control.ToggleButton;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.FlowPane;
import touchline.model.store.SequencedRing;
import touchline.protocol.MessageText;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.time.Instant;
import java.util.Locale;
import java.util.function.Function;
import java.util.function.Predicate;
import touchline.ui.frame.RobotFilter;
import touchline.ui.render.TextColumns;

/**
 * Every datagram in and out: time, direction, peer, size, kind; the selected one as protobuf
 * text (unknown extensions field by field) and as hex. Filters by robot, direction and kind;
 * pause; the newest {@link #SHOWN} rows (up to a tenth more before the oldest go),
 * of which the table holds the last few hundred while it follows the newest ({@link LogList}).
 */
public final class NetworkView implements View {

    static final int SHOWN = 2_000;

    private final ViewContext context;
    private final TableView<Envelope> table = new TableView<>();
    private final TextColumns<Envelope> columns = new TextColumns<>(false);
    private final RobotFilter robot;
    private final ComboBox<String> direction = new ComboBox<>();
    private final TextField kind = new TextField();
    private final ToggleButton pause = new ToggleButton("Pause");
    private final TextArea text = new TextArea();
    private final TextArea hex = new TextArea();
    private final Label count = new Label();
    private final BorderPane root = new BorderPane();
    private final MessageText messageText = new MessageText();
    private final HexLines hexDump = new HexLines();
    private final LogList<Envelope, Envelope> log = new LogList<>(table, SHOWN);

    public NetworkView(ViewContext context) {
        this.context = context;
        this.robot = new RobotFilter(context.field());
        table.setId("network-table");
        robot.setId("network-robot");
        count.setId("network-count");
        table.setFixedCellSize(24);
        table.getColumns().add(columns.column("Time", e -> DebugConsoleView.TIME.format(Instant.ofEpochSecond(0, e.timeMicros() * 1000)), 96,
                "00:00:00.000"));
        table.getColumns().add(column("Dir", e -> e.direction() == Direction.IN ? "in" : "out", 40));
        table.getColumns().add(columns.column("Peer", Envelope::peerText, 130, "127.000.000.100:65535"));
        table.getColumns().add(column("Robot", e -> e.robotId() < 0 ? "–" : Integer.toString(e.robotId()), 50));
        table.getColumns().add(column("Size", e -> Integer.toString(e.size()), 50));
        table.getColumns().add(column("Kind", Envelope::kind, 140));
        table.getColumns().add(column("Channel", e -> e.channel().name(), 90));
        table.getSelectionModel().selectedItemProperty().addListener((o, a, e) -> show(e));
        direction.getItems().addAll("in and out", "in", "out");
        direction.getSelectionModel().select(0);
        kind.setPromptText("kind (e.g. status)");
        robot.valueProperty().addListener((o, a, b) -> log.reload());
        direction.valueProperty().addListener((o, a, b) -> log.reload());
        kind.textProperty().addListener((o, a, b) -> log.reload());
        pause.selectedProperty().addListener((o, a, b) -> {
            if (!b) {
                log.reload();
            }
        });
        text.setEditable(false);
        hex.setEditable(false);
        text.setId("network-text");
        hex.setId("network-hex");
        text.setStyle("-fx-font-family: monospace;");
        hex.setStyle("-fx-font-family: monospace;");
        SplitPane detail = new SplitPane(text, hex);
        SplitPane split = new SplitPane(table, detail);
        split.setOrientation(Orientation.VERTICAL);
        split.setDividerPositions(0.6);
        pause.setMinWidth(javafx.scene.layout.Region.USE_PREF_SIZE);
        FlowPane bar = new FlowPane(8, 4, new Label("Robot"), robot, direction, kind, pause, count); // wraps when narrow
        bar.setStyle("-fx-padding: 4 8 4 8; -fx-alignment: center-left;");
        root.setTop(bar);
        root.setCenter(split);
    }

    private TableColumn<Envelope, String> column(String title, Function<Envelope, String> value, double width) {
        return columns.column(title, value, width, "");
    }

    private void show(Envelope e) {
        if (e == null) {
            return;
        }
        String body;
        if (e.message() != null) {
            body = messageText.render(e.message());
        } else if (e.ros() != null) {
            body = e.ros().typeName() + "\n" + e.ros().text(MessageText.MAX_CHARS);
        } else {
            body = "(no decoded message)";
        }
        if (e.error() != null) {
            body = "NOT DECODED: " + e.error() + "\n" + body;
        }
        text.setText(body);
        hex.setText(e.size() + " bytes\n" + hexDump.dump(e.raw(), 4096));
        hex.positionCaret(0);
    }

    private Predicate<Envelope> filter() {
        int id = robot.robotId();
        String dir = direction.getValue();
        String k = kind.getText() == null ? "" : kind.getText().trim().toLowerCase(Locale.ROOT);
        return e -> (id < 0 || e.robotId() == id)
                && (dir == null || dir.equals("in and out") || (dir.equals("in") == (e.direction() == Direction.IN)))
                && (k.isEmpty() || e.kind().toLowerCase(Locale.ROOT).contains(k));
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        robot.refresh();
        if (pause.isSelected()) {
            log.holdEverything(); // every row scrollable while paused
            return;
        }
        Predicate<Envelope> f = filter();
        // follow the newest until the user picks a row; then the rows on screen stay as the oldest go
        boolean held = !table.getSelectionModel().isEmpty();
        SequencedRing.Entry<Envelope> newest = log.follow(!held, context.stores().network().version(),
                (after, max) -> context.stores().network().since(after, max, f), e -> e);
        if (newest == null) {
            return;
        }
        frame.shown(newest.value().timeMicros());
        count.setText(log.all().size() + " shown of " + context.stores().network().size() + " kept"
                + (held ? " · held at the selected row (Ctrl+click it to follow)" : ""));
    }
}
