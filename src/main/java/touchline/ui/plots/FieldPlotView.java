package touchline.ui.plots;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import javafx.scene.input.KeyCode;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.FlowPane;
import touchline.model.RobotSnapshot;
import touchline.model.store.FieldPlot;
import touchline.model.store.PlotStore;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import touchline.ui.frame.RobotFilter;
import touchline.ui.render.PlotDrawing;

/**
 * Plot anything, like PlotJuggler: choose a field path ({@code kind:path}, every numeric leaf
 * of every message kind seen, the teams' own types included) from a type-to-filter list, for
 * one robot or every robot, and it joins the plot as a series with its colour in the legend;
 * several robots and fields in one plot. Export CSV… writes the plotted data (time, one column
 * per series). The extraction lives in the model ({@link FieldPlot}), fed by the Envelope
 * stream while the view is open: live and replayed data alike.
 */
public final class FieldPlotView implements View {

    private final ViewContext context;
    private final FieldPlot fields;
    private final AutoCloseable subscription;
    private final RobotFilter robot;
    private final TextField path = new TextField();
    private final ListView<String> matches = new ListView<>();
    private final Label status = new Label();
    /** What the last action did (added, exported, why not). */
    private final Label note = new Label();
    private final BorderPane root = new BorderPane();
    private final PlotDrawing plot = new PlotDrawing(() -> dirty = true);
    private long drawnVersion = -1;
    private long listedKinds = -1;
    private boolean dirty;
    private boolean relist = true;
    /** Series of a restored layout whose kind has not been seen yet ({@code robot:kind:path}). */
    private final List<String> pending = new java.util.ArrayList<>();

    public FieldPlotView(ViewContext context) {
        this.context = context;
        this.fields = new FieldPlot(context.field().kinds(), PlotStore.DEFAULT_POINTS, context.field().clock().nowMicros());
        // both streams, as before they were two: a replayed robot shares the live one's series (user guide)
        AutoCloseable live = context.field().bus().subscribe(fields);
        AutoCloseable replayed = context.field().replayStream().subscribe(fields);
        this.subscription = () -> {
            live.close();
            replayed.close();
        };
        this.robot = new RobotFilter(context.field());
        robot.setId("field-robot");
        path.setId("field-path");
        path.setPromptText("field path, e.g. status:battery — Enter adds it");
        path.setPrefColumnCount(24);
        path.textProperty().addListener((o, a, b) -> relist = true);
        path.setOnAction(e -> addChosen());
        path.addEventFilter(javafx.scene.input.KeyEvent.KEY_PRESSED, e -> {
            if (e.getCode() == KeyCode.DOWN) {
                matches.getSelectionModel().selectNext();
                e.consume();
            } else if (e.getCode() == KeyCode.UP) {
                matches.getSelectionModel().selectPrevious();
                e.consume();
            }
        });
        matches.setId("field-paths");
        matches.setPrefWidth(280);
        matches.setOnMouseClicked(e -> {
            if (e.getClickCount() == 2) {
                addChosen();
            }
        });
        matches.setOnKeyPressed(e -> {
            if (e.getCode() == KeyCode.ENTER) {
                addChosen();
            }
        });
        Button add = new Button("Add");
        add.setOnAction(e -> addChosen());
        Button removeLast = new Button("Remove last");
        removeLast.setOnAction(e -> {
            List<FieldPlot.Series> s = fields.series();
            if (!s.isEmpty()) {
                fields.remove(s.get(s.size() - 1));
            }
        });
        Button export = new Button("Export CSV…");
        export.setId("field-export");
        export.setOnAction(e -> chooseCsv());
        javafx.scene.control.CheckBox perSeries = new javafx.scene.control.CheckBox("Axis per series");
        perSeries.setId("field-axis-per-series");
        perSeries.setTooltip(new javafx.scene.control.Tooltip(
                "Off: one y axis per unit read from the field's name (…_mm, …Percent, battery, …_deg, …_rad, …_ms)"));
        perSeries.setOnAction(e -> {
            plot.axisPerSeries(perSeries.isSelected());
            dirty = true;
        });
        status.setId("field-status");
        note.setId("field-note");
        root.addEventFilter(javafx.scene.input.KeyEvent.KEY_PRESSED, e -> {
            if (e.isShortcutDown() && e.getCode() == KeyCode.F) {
                path.requestFocus();
                path.selectAll();
                e.consume();
            }
        });
        FlowPane bar = new FlowPane(8, 4, new Label("Robot"), robot, path, add, removeLast, perSeries, export, status, note);
        bar.setStyle("-fx-padding: 4 8 4 8; -fx-alignment: center-left;");
        root.setTop(bar);
        root.setLeft(matches);
        plot.node().setId("field-canvas");
        root.setCenter(plot.node());
    }

    /** The series plotted: {@code touchline screenshots} adds the user guide's picture's series through it. */
    public FieldPlot fields() {
        return fields;
    }

    /** Adds the chosen path (the list's selection, else the typed text) for the chosen robot or every robot seen. */
    private void addChosen() {
        String chosen = matches.getSelectionModel().getSelectedItem();
        if (chosen == null) {
            chosen = path.getText() == null ? "" : path.getText().trim();
        }
        int id = robot.robotId();
        List<Integer> robots = id >= 0 ? List.of(id)
                : context.field().robots().robots().stream().map(RobotSnapshot::id).distinct().toList();
        int added = 0;
        for (int r : robots) {
            if (fields.add(r, chosen)) {
                added++;
            }
        }
        if (added == 0 && fields.add(touchline.transport.Envelope.NO_ROBOT, chosen)) {
            added++; // a topic of a ROS 2 bag, whose messages belong to no robot
        }
        note.setText(added > 0 ? "added " + chosen + " for " + (id >= 0 ? "robot " + id : added + " robots")
                : chosen.isEmpty() ? "choose a field path first"
                : chosen + ": no numeric field of a kind seen, or already plotted");
    }

    /** Asks where to write the CSV in a dialog that leaves a maximised window maximised ({@link SaveAsDialog}). */
    private void chooseCsv() {
        new touchline.ui.window.SaveAsDialog(root.getScene().getWindow(), "Export the plotted data as CSV",
                Path.of(System.getProperty("user.home"), "plot.csv")).ask(this::exportCsv);
    }

    /** Writes the plotted data as CSV; the status line says where, or why not. */
    public void exportCsv(Path file) {
        try {
            Files.writeString(file, fields.csv(), StandardCharsets.UTF_8);
            note.setText("exported " + fields.series().size() + " series to " + file);
        } catch (IOException e) {
            note.setText("could not export to " + file + ": " + e.getMessage());
        }
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        robot.refresh();
        long kindsVersion = fields.kindsVersion();
        if (kindsVersion != listedKinds && !pending.isEmpty()) {
            pending.removeIf(this::addSaved); // their kind arrived
        }
        if (relist || kindsVersion != listedKinds) {
            relist = false;
            listedKinds = kindsVersion;
            String keep = matches.getSelectionModel().getSelectedItem();
            List<String> found = fields.paths(path.getText());
            if (!found.equals(matches.getItems())) {
                matches.getItems().setAll(found);
            }
            int i = keep == null ? -1 : found.indexOf(keep);
            matches.getSelectionModel().select(Math.max(0, i));
        }
        long v = fields.version();
        if (v == drawnVersion && !dirty) {
            return;
        }
        drawnVersion = v;
        dirty = false;
        List<PlotStore.SeriesData> series = fields.snapshot();
        if (series.isEmpty()) {
            plot.empty();
            status.setText("no series: choose a field path, Enter adds it");
            return;
        }
        int points = plot.draw(series);
        status.setText(series.size() + " series · " + points + " points");
    }

    /** The plotted series (and those still waiting for their kind): {@code series=3:status:battery;1:status:x}. */
    @Override
    public String layoutState() {
        StringBuilder s = new StringBuilder(STATE_PREFIX);
        for (FieldPlot.Series series : fields.series()) {
            s.append(series.robotId()).append(':').append(series.kind()).append(':').append(series.path()).append(';');
        }
        pending.forEach(p -> s.append(p).append(';'));
        return s.toString();
    }

    /** Plots a saved layout's series again, each once its kind has been seen. */
    @Override
    public void restoreLayoutState(String state) {
        if (state == null || !state.startsWith(STATE_PREFIX)) {
            return;
        }
        for (String saved : state.substring(STATE_PREFIX.length()).split(";")) {
            if (!saved.isBlank() && !addSaved(saved)) {
                pending.add(saved);
            }
        }
    }

    private static final String STATE_PREFIX = "series=";

    /** Adds one saved {@code robot:kind:path}; false while its kind has not been seen (or it is not a series). */
    private boolean addSaved(String saved) {
        int colon = saved.indexOf(':');
        try {
            return colon > 0 && fields.add(Integer.parseInt(saved.substring(0, colon)), saved.substring(colon + 1));
        } catch (NumberFormatException e) {
            return true; // not a series: dropped, as the layout reader drops what it does not understand
        }
    }

    @Override
    public void close() {
        try {
            subscription.close();
        } catch (Exception e) {
            // unsubscribing cannot fail
        }
    }
}
