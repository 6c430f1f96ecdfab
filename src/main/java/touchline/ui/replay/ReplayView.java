package touchline.ui.replay;

import touchline.app.TeamSchemas;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.CheckBox;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.ScrollPane;
import javafx.scene.control.Separator;
import javafx.scene.control.TextField;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.VBox;
import javafx.stage.FileChooser;
import javafx.util.StringConverter;
import touchline.app.LiveField;
import touchline.app.Replay;
import touchline.record.PlayerState;
import touchline.record.ReplayNotes;
import touchline.record.RecordingException;
import touchline.record.TimelineEvent;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Record and replay in one view: record the session to an MCAP file; open a recording and
 * drive it with a timeline (events, seek, loop A–B), play/pause, speed and seek-to-event;
 * choose whether live traffic keeps flowing beside the replay; load a team's own message
 * types. The replay feeds the console's one Envelope stream, so every other view shows it.
 * Everything that reads a file or may wait on the console's lock runs on a background thread;
 * the player's state is pulled once per frame.
 */
public final class ReplayView implements View {

    static final List<Double> SPEEDS = List.of(0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 10.0, 25.0, 50.0);

    private final LiveField field;
    private final ReplayViewModel model;
    private final TeamSchemas schemas;
    private final WorkQueue work;
    private final WorkQueue scans;
    private final RecordPanel record;
    private final TimelineCanvas timeline;
    private final TextField path = new TextField();
    private final Label message = new Label();
    private final ListView<String> problems = new ListView<>();
    private final Label notesBadge = new Label();
    private final javafx.scene.control.Tooltip notesTip = new javafx.scene.control.Tooltip();
    private final Button play = new Button("▶ Play");
    private final ComboBox<Double> speed = new ComboBox<>();
    private final Label position = new Label("No recording open.");
    private final Label loop = new Label();
    private final Label files = new Label();
    private final CheckBox live = new CheckBox("Live listening");
    private final ListView<String> schemaList = new ListView<>();
    private final List<Node> replayControls = new ArrayList<>();
    private final AtomicLong pendingSeek = new AtomicLong(-1);
    private final VBox root;
    private final ScrollPane scroll;
    private Replay shown;
    private PlayerState state;
    private List<TimelineEvent> events = List.of();
    private ReplayNotes shownNotes = ReplayNotes.NONE;
    /** The message speaks of the replay that is open ("Opened …", "No goal after …"): it goes with it. */
    private boolean messageOfReplay;

    public ReplayView(ViewContext context) {
        this.field = context.field();
        this.model = new ReplayViewModel(context.replays());
        this.schemas = context.schemas();
        this.work = new WorkQueue("touchline-replay-view", this::fail);
        this.scans = new WorkQueue("touchline-replay-events", this::fail);
        this.record = new RecordPanel(context.recordings(), field.clock(), work);
        this.timeline = new TimelineCanvas(this::requestSeek);
        root = new VBox(10, record.node(), new Separator(), replayPane(), new Separator(), schemaPane());
        root.setStyle("-fx-padding: 8;");
        scroll = new ScrollPane(root);
        scroll.setFitToWidth(true);
    }

    private Node replayPane() {
        path.setId("replay-path");
        path.setPromptText("recording.mcap  (several: laptop.mcap; robot3.mcap or robot3.mcap=+1.250 with its clock offset)");
        path.setOnAction(e -> open());
        HBox.setHgrow(path, Priority.ALWAYS);
        Button browse = new Button("Browse…");
        browse.setOnAction(e -> browse());
        Button open = button("replay-open", "Open", this::open);
        Button add = button("replay-add", "Add file…", this::addFiles);
        Button close = button("replay-close", "Close replay", () -> work.run(model::closeReplay));
        // the path on a row of its own: beside four buttons it shrank to nothing in the demo layout's
        // left pane at 1280 px (the "File" label cut to "…")
        path.setMinWidth(160);
        HBox fileRow = row(new Label("File"), path);
        HBox fileButtons = row(browse, open, add, close);
        files.setId("replay-files");
        files.setWrapText(true);
        files.setVisible(false);
        files.setManaged(false);

        message.setId("replay-message");
        message.setWrapText(true);
        problems.setId("replay-problems");
        problems.setPrefHeight(60);
        problems.setVisible(false);
        problems.setManaged(false);
        // what was skipped, said as replay says it: a badge, its tooltip and the list below it
        notesBadge.setId("replay-notes");
        notesBadge.setWrapText(true);
        notesBadge.setStyle("-fx-text-fill: #9a6700; -fx-font-weight: bold;");
        notesBadge.setTooltip(notesTip);
        notesBadge.managedProperty().bind(notesBadge.textProperty().isNotEmpty());
        notesBadge.visibleProperty().bind(notesBadge.textProperty().isNotEmpty());

        play.setId("replay-play");
        play.setOnAction(e -> playOrPause());
        play.setMinWidth(80);
        speed.setId("replay-speed");
        speed.getItems().setAll(SPEEDS);
        speed.setValue(1.0);
        speed.setConverter(new StringConverter<>() {
            @Override
            public String toString(Double d) {
                return d == null ? "" : speedText(d);
            }

            @Override
            public Double fromString(String s) {
                return Double.parseDouble(s.replace("×", "").trim());
            }
        });
        speed.setOnAction(e -> {
            Replay r = shown;
            Double v = speed.getValue();
            if (r != null && v != null) {
                work.run(() -> r.setSpeed(v));
            }
        });
        Button goal = button("replay-next-goal", "Next goal", () -> next(TimelineEvent.Type.GOAL));
        Button change = button("replay-next-state", "Next state change", () -> next(TimelineEvent.Type.STATE_CHANGE));
        Button lost = button("replay-next-lost", "Next robot lost", () -> next(TimelineEvent.Type.ROBOT_LOST));
        Button penalty = button("replay-next-penalty", "Next penalty", () -> next(TimelineEvent.Type.PENALTY));
        goal.setStyle("-fx-border-color: #d4a72c; -fx-border-width: 0 0 3 0;");
        change.setStyle("-fx-border-color: #2f81f7; -fx-border-width: 0 0 3 0;");
        lost.setStyle("-fx-border-color: #cf222e; -fx-border-width: 0 0 3 0;");
        penalty.setStyle("-fx-border-color: #e16f24; -fx-border-width: 0 0 3 0;");
        Button a = button("replay-loop-a", "Loop A", this::setLoopA);
        Button b = button("replay-loop-b", "Loop B", this::setLoopB);
        Button clear = button("replay-loop-clear", "Clear loop", this::clearLoop);
        // wraps on a narrow window, so the file row above keeps its Open button in view
        javafx.scene.layout.FlowPane controls = new javafx.scene.layout.FlowPane(8, 6, play, new Label("Speed"), speed,
                goal, change, penalty, lost, a, b, clear, loop);
        controls.setStyle("-fx-alignment: center-left;");
        replayControls.addAll(List.of(play, speed, goal, change, penalty, lost, a, b, clear, close));

        position.setId("replay-position");
        live.setId("replay-live");
        live.setOnAction(e -> field.setLiveListening(live.isSelected()));
        live.setSelected(field.liveListening());
        Label hint = new Label("(off: only the replay feeds the views, and their clock follows it)");
        hint.setStyle("-fx-opacity: 0.7;");
        Label title = new Label("Replay");
        title.setStyle("-fx-font-weight: bold;");
        return new VBox(6, title, fileRow, fileButtons, message, notesBadge, problems, timeline.node(), files, position, controls, row(live, hint));
    }

    private Node schemaPane() {
        Label title = new Label("Team schemas");
        title.setStyle("-fx-font-weight: bold;");
        Button load = button("schema-load", "Load team schema…", this::chooseSchema);
        Label hint = new Label("a protoc descriptor set: protoc --include_imports --descriptor_set_out=team.desc team.proto");
        hint.setStyle("-fx-opacity: 0.7;");
        schemaList.setId("schema-list");
        schemaList.setPrefHeight(80);
        schemaList.setPlaceholder(new Label("No team schema loaded: the built-in FUmanoids types decode."));
        return new VBox(6, title, row(load, hint), schemaList);
    }

    private static HBox row(Node... nodes) {
        HBox row = new HBox(8, nodes);
        row.setStyle("-fx-alignment: center-left;");
        return row;
    }

    private static Button button(String id, String text, Runnable action) {
        Button b = new Button(text);
        b.setId(id);
        b.setOnAction(e -> action.run());
        return b;
    }

    static String speedText(double s) {
        return ReplayViewModel.speedText(s);
    }

    private void fail(String why) {
        message.setText(why);
        message.setStyle("-fx-text-fill: #cf222e;");
        messageOfReplay = false;
    }

    private void say(String text) {
        message.setText(text);
        message.setStyle("");
        messageOfReplay = false;
    }

    /** Says something about the open replay: the message is cleared when the replay closes. */
    private void sayOfReplay(String text) {
        say(text);
        messageOfReplay = true;
    }

    // ---- actions (FX thread); anything slow goes to the work queue ----

    /** Chooses one or several recordings (several play as one session) and opens them. */
    private void browse() {
        List<Path> chosen = choose("Open recording(s)");
        if (!chosen.isEmpty()) {
            path.setText(new SessionFiles(chosen, java.util.Map.of()).text());
            open();
        }
    }

    /** Adds recordings to the files in the field (the open session) and opens them all as one session. */
    private void addFiles() {
        List<Path> chosen = choose("Add recording(s) to the session");
        if (!chosen.isEmpty()) {
            path.setText(SessionFiles.parse(path.getText()).plus(chosen).text());
            open();
        }
    }

    private List<Path> choose(String title) {
        FileChooser chooser = new FileChooser();
        chooser.setTitle(title);
        chooser.getExtensionFilters().addAll(new FileChooser.ExtensionFilter("MCAP recordings", "*.mcap"),
                new FileChooser.ExtensionFilter("All files", "*"));
        javafx.stage.Window window = root.getScene().getWindow();
        List<java.io.File> f = new touchline.ui.window.StaysMaximised(window).during(() -> chooser.showOpenMultipleDialog(window));
        return f == null ? List.of() : f.stream().map(java.io.File::toPath).toList();
    }

    /**
     * Opens the file(s) named in the path field (paused at the start): several, separated by
     * {@code ;}, play as one session on one timeline ({@link SessionFiles}).
     */
    void open() {
        java.util.Optional<String> refusal = ReplayViewModel.refusal(path.getText());
        if (refusal.isPresent()) {
            fail(refusal.get());
            return;
        }
        SessionFiles chosen = SessionFiles.parse(path.getText());
        String names = chosen.names();
        say("Opening " + names + (chosen.files().size() > 1 ? " (aligning their clocks) …" : " …"));
        work.run(() -> {
            try {
                model.open(chosen);
                work.handOff(() -> sayOfReplay("Opened " + names + "."));
            } catch (RecordingException e) {
                work.handOff(() -> fail("Cannot replay " + names + ": " + e.getMessage()));
            }
        });
    }

    private void playOrPause() {
        Replay r = shown;
        if (r == null) {
            return;
        }
        boolean playing = state != null && state.playing();
        Double v = speed.getValue();
        work.run(() -> {
            if (playing) {
                r.pause();
            } else {
                if (v != null) {
                    r.setSpeed(v);
                }
                r.play();
            }
        });
    }

    private void next(TimelineEvent.Type type) {
        Replay r = shown;
        if (r == null) {
            return;
        }
        work.run(() -> {
            if (r.seekToNext(type).isEmpty()) {
                work.handOff(() -> sayOfReplay(ReplayViewModel.noneAfter(type)));
            }
        });
    }

    /** Seeks (coalesced: a drag asks many times, the player only seeks to the newest). */
    private void requestSeek(long micros) {
        Replay r = shown;
        if (r == null) {
            return;
        }
        if (pendingSeek.getAndSet(micros) < 0) {
            work.run(() -> {
                long t = pendingSeek.getAndSet(-1);
                if (t >= 0) {
                    r.seek(t);
                }
            });
        }
    }

    private void setLoopA() {
        if (state != null) {
            loop.setText(model.markA(state));
        }
    }

    private void setLoopB() {
        Replay r = shown;
        if (r == null || state == null) {
            return;
        }
        ReplayViewModel.LoopB b = model.markB(state);
        if (b.refusal() != null) {
            loop.setText(b.refusal());
            return;
        }
        work.run(() -> r.setLoop(b.fromMicros(), b.toMicros()));
    }

    private void clearLoop() {
        Replay r = shown;
        model.clearMark();
        loop.setText("");
        if (r != null) {
            work.run(r::clearLoop);
        }
    }

    private void chooseSchema() {
        FileChooser chooser = new FileChooser();
        chooser.setTitle("Load team schema (protoc descriptor set)");
        chooser.getExtensionFilters().addAll(new FileChooser.ExtensionFilter("Descriptor sets", "*.desc", "*.pb"),
                new FileChooser.ExtensionFilter("All files", "*"));
        javafx.stage.Window window = root.getScene().getWindow();
        java.io.File f = new touchline.ui.window.StaysMaximised(window).during(() -> chooser.showOpenDialog(window));
        if (f != null) {
            loadSchema(f.toPath());
        }
    }

    /** Loads a team's descriptor set in the background; the list shows what it brought. */
    void loadSchema(Path file) {
        work.run(() -> {
            List<String> lines = new ArrayList<>();
            try {
                TeamSchemas.Outcome o = schemas.load(file);
                o.extensions().forEach(x -> lines.add("✔ " + x));
                o.refusals().forEach(x -> lines.add("✖ " + x));
            } catch (RecordingException e) {
                lines.add("✖ " + e.getMessage());
            }
            work.handOff(() -> schemaList.getItems().addAll(lines));
        });
    }

    // ---- once per frame ----

    @Override
    public Node node() {
        return scroll;
    }

    @Override
    public void refresh(FrameContext frame) {
        work.drain();
        scans.drain();
        record.refresh();
        if (live.isSelected() != field.liveListening()) {
            live.setSelected(field.liveListening());
        }
        if (work.busy()) {
            return; // a file operation may hold the console or player lock: never wait for it here
        }
        Replay r = model.current().orElse(null);
        if (r != shown) {
            adopt(r);
        }
        state = r == null ? null : r.state();
        timeline.show(state, events);
        showState();
    }

    /** A new replay (or none): its events are read on the scan thread (the first read scans the file). */
    private void adopt(Replay r) {
        shown = r;
        events = List.of();
        if (r == null && messageOfReplay) {
            say("");
        }
        model.clearMark();
        loop.setText("");
        replayControls.forEach(n -> n.setDisable(r == null));
        List<String> aligned = ReplayViewModel.alignedFiles(r);
        files.setText(String.join("\n", aligned));
        files.setTooltip(aligned.isEmpty() ? null : new javafx.scene.control.Tooltip(
                "Each file's clock moved onto the first file's: by the GameController packets both heard "
                        + "(median difference; 'agree within' = 95% of them), or by the offset given as file=+seconds"));
        files.setVisible(!aligned.isEmpty());
        files.setManaged(!aligned.isEmpty());
        if (r != null) {
            scans.run(() -> {
                List<TimelineEvent> ev = r.events();
                scans.handOff(() -> {
                    if (shown == r) {
                        events = ev;
                    }
                });
            });
        }
    }

    private void showState() {
        ReplayNotes notes = state == null ? ReplayNotes.NONE : state.notes();
        if (!notes.equals(shownNotes)) {
            shownNotes = notes;
            List<String> items = ReplayViewModel.noteLines(notes);
            problems.getItems().setAll(items);
            problems.setVisible(!items.isEmpty());
            problems.setManaged(!items.isEmpty());
            notesBadge.setText(notes.badge());
            notesTip.setText(String.join("\n", notes.lines()));
        }
        String text = ReplayViewModel.position(state, events.size(), events.isEmpty() && shown != null && scans.busy());
        model.loopLine(state).ifPresent(loop::setText);
        if (!text.equals(position.getText())) {
            position.setText(text);
        }
        String label = state != null && state.playing() ? "❚❚ Pause" : "▶ Play";
        if (!label.equals(play.getText())) {
            play.setText(label);
        }
    }

    /** The timeline's events as shown now (FX thread; for tests). */
    List<TimelineEvent> shownEvents() {
        return timeline.events();
    }

    TimelineCanvas timeline() {
        return timeline;
    }

    @Override
    public void close() {
        work.close();
        scans.close();
    }
}
