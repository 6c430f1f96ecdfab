package touchline.ui.ros2;

import touchline.ui.render.TextColumns;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.TableView;
import javafx.scene.control.TextField;
import javafx.scene.input.KeyCode;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import touchline.app.bridges.RosBridges;
import touchline.transport.SendResult;
import touchline.transport.remote.Bridge;
import touchline.transport.remote.BridgeStatus;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.util.ArrayList;
import java.util.List;

/**
 * The ROS 2 robots' parameters (their bridges' capability {@code parameters}): read, refreshed
 * on request, edited (a value typed and Set), a bool toggled with Space or a double-click like
 * a debug option. Every change passes the console's send gate: held during play (and sent
 * when it stops), refused on a viewing console; the status line says which.
 */
public final class ParametersView implements View {

    /** One parameter of one robot as the table shows it. */
    public record Row(int robotId, String robot, String name, Object value) {
        String valueText() {
            return value == null ? "–" : String.valueOf(value);
        }
    }

    private final RosBridges bridges;
    private final TableView<Row> table = new TableView<>();
    private final TextField value = new TextField();
    private final Button set = new Button("Set");
    private final Button refresh = new Button("Refresh");
    private final Label status = new Label();
    private final BorderPane root = new BorderPane();
    private long shownVersion = -1;

    public ParametersView(ViewContext context) {
        this.bridges = context.bridges();
        table.setId("parameters-table");
        table.setPlaceholder(new Label("No ROS 2 robot's parameters (console --connect NAME=ws://…, Refresh)"));
        TextColumns<Row> columns = new TextColumns<>(false);
        table.getColumns().add(columns.column("Robot", Row::robot, 120, ""));
        table.getColumns().add(columns.column("Parameter", Row::name, 200, ""));
        table.getColumns().add(columns.column("Value", Row::valueText, 160, ""));
        table.setOnKeyPressed(e -> {
            if (e.getCode() == KeyCode.SPACE) {
                toggle();
                e.consume();
            }
        });
        table.setOnMouseClicked(e -> {
            if (e.getClickCount() == 2) {
                toggle();
            }
        });
        table.getSelectionModel().selectedItemProperty().addListener((o, a, r) -> value.setText(r == null ? ""
                : r.valueText()));
        value.setId("parameters-value");
        value.setPromptText("new value");
        value.setOnAction(e -> setTyped());
        set.setId("parameters-set");
        set.setOnAction(e -> setTyped());
        refresh.setId("parameters-refresh");
        refresh.setOnAction(e -> refreshAll());
        status.setId("parameters-status");
        HBox controls = new HBox(8, refresh, value, set);
        controls.setStyle("-fx-alignment: center-left;");
        VBox top = new VBox(6, controls, status);
        top.setStyle("-fx-padding: 6 8 6 8;");
        root.setTop(top);
        root.setCenter(table);
    }

    private void refreshAll() {
        List<String> said = new ArrayList<>();
        for (BridgeStatus b : bridges.statuses()) {
            said.add(b.name() + ": " + bridges.refreshParameters(b.robotId()).describe());
        }
        status.setText(said.isEmpty() ? "no ROS 2 robot connected" : String.join("  ·  ", said));
    }

    private void toggle() {
        Row r = table.getSelectionModel().getSelectedItem();
        if (r != null && r.value() instanceof Boolean b) {
            say(r, !b, bridges.setParameter(r.robotId(), r.name(), !b));
        }
    }

    private void setTyped() {
        Row r = table.getSelectionModel().getSelectedItem();
        if (r == null) {
            status.setText("choose a parameter first");
            return;
        }
        Object v = typed(value.getText().strip(), r.value());
        say(r, v, bridges.setParameter(r.robotId(), r.name(), v));
    }

    private void say(Row r, Object v, SendResult result) {
        status.setText(r.robot() + " " + r.name() + " = " + v + ": " + result.describe());
    }

    /** The text as the parameter's kind: a bool, a number, else a string. */
    static Object typed(String text, Object old) {
        if (text.equalsIgnoreCase("true") || text.equalsIgnoreCase("false")) {
            return Boolean.parseBoolean(text);
        }
        try {
            return old instanceof Double || old instanceof Float || text.contains(".") ? (Object) Double.parseDouble(text)
                    : (Object) Long.parseLong(text);
        } catch (NumberFormatException e) {
            return text;
        }
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        long v = bridges.parametersVersion();
        if (v == shownVersion) {
            return;
        }
        shownVersion = v;
        List<Row> rows = new ArrayList<>();
        for (BridgeStatus b : bridges.statuses()) {
            for (Bridge.Parameter p : bridges.parameters(b.robotId())) {
                rows.add(new Row(b.robotId(), b.name(), p.name(), p.value()));
            }
        }
        Row selected = table.getSelectionModel().getSelectedItem();
        table.getItems().setAll(rows);
        if (selected != null) {
            rows.stream().filter(r -> r.robotId() == selected.robotId() && r.name().equals(selected.name())).findFirst()
                    .ifPresent(r -> table.getSelectionModel().select(r));
        }
    }
}
