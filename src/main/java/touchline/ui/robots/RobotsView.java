package touchline.ui.robots;

import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.SplitPane;
import javafx.scene.control.TableCell;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableView;
import javafx.scene.control.TextArea;
import javafx.geometry.Orientation;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.VBox;
import touchline.model.RobotSnapshot;
import touchline.model.SourceSnapshot;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.util.List;
import java.util.function.Function;
import touchline.ui.render.FittedTable;
import touchline.ui.render.LiveRows;
import touchline.ui.render.TextColumns;

/**
 * Every robot ever seen, one row each, with online/offline at a glance; below, the senders
 * whose datagrams were rejected and the registry's notes (address changes, duplicate IDs).
 * Rows are brought up to date at most twice a second (rates and "last seen" need no more), and
 * only the cells whose text changed ({@link LiveRows}).
 */
public final class RobotsView implements View {

    /** The online column's text for a robot online; its colour follows it. */
    private static final String ONLINE = "●";

    /** A row's height: the theme's, fixed so the table can be as tall as its rows. */
    private static final double ROW_HEIGHT = 40;

    private final ViewContext context;
    private final TableView<LiveRows.Row<RobotSnapshot>> table = new FittedTable<>(ROW_HEIGHT, 3);
    private final TextColumns<LiveRows.Row<RobotSnapshot>> columns = new TextColumns<>(true);
    private final TextArea problems = new TextArea();
    private final SplitPane root = new SplitPane();
    /** What each column shows of a robot, in column order. */
    private final TableColumn<LiveRows.Row<RobotSnapshot>, String> temperature;
    private final List<Function<RobotSnapshot, String>> shownTexts = new java.util.ArrayList<>();
    private final LiveRows<RobotSnapshot> rows = new LiveRows<>(r -> r.id() + "/" + r.origin(),
            r -> shownTexts.stream().map(f -> f.apply(r)).toList());
    private long lastRebuildMicros;
    private long seenVersion = -1;

    public RobotsView(ViewContext context) {
        this.context = context;
        table.setId("robot-table");
        table.setPlaceholder(new Label("No robot seen yet: robots send keep-alives to UDP port "
                + context.field().port()));
        TableColumn<LiveRows.Row<RobotSnapshot>, String> online = column("", r -> r.online() ? ONLINE : "○", 36);
        online.setCellFactory(c -> new TableCell<>() {
            @Override
            protected void updateItem(String item, boolean empty) {
                super.updateItem(item, empty);
                setText(empty ? null : item);
                setStyle(empty || item == null ? "" : item.equals(ONLINE) ? "-fx-text-fill: #2da44e;" : "-fx-text-fill: #cf222e;");
            }
        });
        table.getColumns().add(online);
        // what a team watches in a game first (Game and Authenticity inside the demo layout's left pane
        // at 1280 pixels, no sideways scroll), the traffic after
        table.getColumns().add(column("ID", r -> Integer.toString(r.id()), 44));
        table.getColumns().add(column("Name", r -> text(r.label()), 80)); // "robot 3 (replay)" for a replayed one
        table.getColumns().add(column("Battery", r -> r.batteryPercent() < 0 ? "–" : r.batteryPercent() + " %", 64));
        temperature = column("Temp.", r -> Double.isNaN(r.temperature()) ? "–" : String.format("%.0f °C", r.temperature()), 56);
        temperature.setVisible(false); // shown once a ROS 2 robot reports one (small robots do not)
        table.getColumns().add(temperature);
        table.getColumns().add(column("Game", r -> text(r.gameStateShown()), 80));
        table.getColumns().add(column("Authenticity", r -> r.auth().describe(), 100));
        // the league's debug rule in play (issue 40): datagrams per period, the biggest and its fragments
        table.getColumns().add(column("Debug in play", this::inPlay, 150, "⚠ 2.0/period, 1400 B, 1 fr."));
        table.getColumns().add(column("Role", r -> text(r.role()), 90));
        table.getColumns().add(column("State", r -> text(r.state()), 90));
        table.getColumns().add(column("Team", r -> number(r.teamId()), 50));
        table.getColumns().add(column("Online for", r -> duration(r.timeOnlineSeconds()), 72));
        table.getColumns().add(column("Last seen", r -> ago((r.replayed() ? context.field().replayClock()
                : context.field().clock()).nowMicros() - r.lastSeenMicros()), 76));
        table.getColumns().add(column("Status", r -> r.online() ? "online" : "offline", 64));
        table.getColumns().add(column("Packets/s", r -> String.format("%.1f", r.packetsPerSecond()), 72));
        table.getColumns().add(column("Bytes/s", r -> String.format("%.0f", r.bytesPerSecond()), 72));
        table.getColumns().add(column("Malformed", r -> Long.toString(r.malformed()), 72));
        Function<RobotSnapshot, String> address = r -> r.address() == null ? "" : r.address().getHostString()
                + ":" + r.address().getPort();
        table.getColumns().add(column("Address", address, 130, "127.000.000.100:65535"));
        problems.setEditable(false);
        problems.setPrefRowCount(4);
        problems.setPromptText("Bad sources and notes appear here.");
        root.setOrientation(Orientation.VERTICAL);
        BorderPane bottom = new BorderPane(problems);
        bottom.setTop(new Label(" Bad sources and notes"));
        root.getItems().addAll(new VBox(table), bottom);
        root.setDividerPositions(0.75);
    }

    private TableColumn<LiveRows.Row<RobotSnapshot>, String> column(String title, Function<RobotSnapshot, String> value,
                                                                     double width) {
        return column(title, value, width, "");
    }

    /** A column showing {@code value} of each robot; its cells change only when their text does. */
    private TableColumn<LiveRows.Row<RobotSnapshot>, String> column(String title, Function<RobotSnapshot, String> value,
                                                                     double width, String widest) {
        int index = shownTexts.size();
        shownTexts.add(value);
        return columns.observed(title, row -> row.text(index), width, widest);
    }

    /** "1.0/period, 412 B, 1 fr." while the robot is in play, "⚠ …" when it breaks the rule; "–" outside play. */
    private String inPlay(RobotSnapshot r) {
        if (r.replayed()) {
            return "–";
        }
        touchline.model.MatchDebugRule.Reading m = context.field().matchRule().reading(r.id());
        if (!m.inPlay()) {
            return "–";
        }
        return (m.warnings().isEmpty() ? "" : "⚠ ") + String.format("%.1f/period, %d B, %d fr.", m.perPeriod(),
                m.biggestBytes(), m.fragments());
    }

    private static String text(String s) {
        return s == null || s.isEmpty() ? "–" : s;
    }

    private static String number(int n) {
        return n == RobotSnapshot.UNKNOWN ? "–" : Integer.toString(n);
    }

    static String duration(long seconds) {
        if (seconds < 0) {
            return "–";
        }
        return seconds >= 3600 ? String.format("%d:%02d:%02d", seconds / 3600, seconds / 60 % 60, seconds % 60)
                : String.format("%d:%02d", seconds / 60, seconds % 60);
    }

    static String ago(long micros) {
        double s = micros / 1e6;
        return s < 1 ? "now" : s < 120 ? String.format("%.0f s ago", s) : String.format("%.0f min ago", s / 60);
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        long v = context.field().robots().version();
        // keep-alives change the version many times a second; rates and "last seen" only need
        // two updates a second, but a robot appearing shows at once
        if (v == seenVersion || (frame.nowMicros() - lastRebuildMicros < 500_000
                && context.field().robots().robots().size() == table.getItems().size())) {
            return;
        }
        seenVersion = v;
        lastRebuildMicros = frame.nowMicros();
        rows.update(table.getItems(), context.field().robots().robots());
        temperature.setVisible(table.getItems().stream().anyMatch(r -> !Double.isNaN(r.value().temperature())));
        StringBuilder p = new StringBuilder();
        for (SourceSnapshot s : context.field().robots().sources()) {
            if (s.malformed() > 0) {
                p.append(s.label()).append(": ").append(s.malformed()).append(" malformed of ").append(s.packets())
                        .append(s.lastError() == null ? "" : " — last: " + s.lastError()).append('\n');
            }
        }
        for (String n : context.field().robots().notes()) {
            p.append(n).append('\n');
        }
        for (touchline.model.MatchDebugRule.Reading m : context.field().matchRule().broken()) {
            p.append("robot ").append(m.robotId()).append(" breaks the debug rule in play: ")
                    .append(String.join("; ", m.warnings())).append('\n');
        }
        if (!p.toString().equals(problems.getText())) {
            problems.setText(p.toString());
        }
    }
}
