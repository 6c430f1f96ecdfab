package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.CheckBox;
import javafx.scene.control.Label;
import javafx.scene.control.Labeled;
import javafx.scene.control.ScrollPane;
import javafx.scene.control.Separator;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import touchline.app.LiveField;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.nio.file.Path;

/**
 * Record and replay in one view: record the session to an MCAP file; open a recording and
 * drive it with a timeline (events, seek, loop A–B), play/pause, speed and seek-to-event;
 * choose whether live traffic keeps flowing beside the replay; load a team's own message
 * types. The replay feeds the console's replay stream, so every other view shows it.
 * The view only binds: what it does and shows is the {@link ReplayViewModel}, whose slow calls
 * run on a background thread; the player's state is pulled once per frame.
 */
public final class ReplayView implements View {

    private final LiveField field;
    private final ReplayViewModel model;
    private final RecordPanel record;
    private final SessionPicker picker;
    private final ReplayNotesPane notes = new ReplayNotesPane();
    private final TimelineCanvas timeline;
    private final TransportBar transport;
    private final SchemaPane schemas;
    private final Label position = new Label("No recording open.");
    private final CheckBox live = new CheckBox("Live listening");
    private final ScrollPane scroll;

    public ReplayView(ViewContext context) {
        this.field = context.field();
        this.model = new ReplayViewModel(context.replays(), context.schemas());
        this.record = new RecordPanel(context.recordings(), field.clock(), model.work());
        this.picker = new SessionPicker(model);
        this.timeline = new TimelineCanvas(model::seek);
        this.transport = new TransportBar(model);
        this.schemas = new SchemaPane(model);
        position.setId("replay-position");
        live.setId("replay-live");
        live.setOnAction(e -> field.setLiveListening(live.isSelected()));
        live.setSelected(field.liveListening());
        Label hint = new Label("(off: only the replay feeds the views, and their clock follows it)");
        hint.setStyle("-fx-opacity: 0.7;");
        Label title = new Label("Replay");
        title.setStyle("-fx-font-weight: bold;");
        VBox replay = new VBox(6, title, picker.node(), notes.node(), timeline.node(), picker.files(), position,
                transport.node(), row(live, hint));
        VBox root = new VBox(10, record.node(), new Separator(), replay, new Separator(), schemas.node());
        root.setStyle("-fx-padding: 8;");
        scroll = new ScrollPane(root);
        scroll.setFitToWidth(true);
    }

    static HBox row(Node... nodes) {
        HBox row = new HBox(8, nodes);
        row.setStyle("-fx-alignment: center-left;");
        return row;
    }

    static Button button(String id, String text, Runnable action) {
        Button b = new Button(text);
        b.setId(id);
        b.setOnAction(e -> action.run());
        return b;
    }

    /** Sets a label's text only when it differs (a set text lays the scene out again). */
    static void setIfChanged(Labeled labeled, String text) {
        if (!text.equals(labeled.getText())) {
            labeled.setText(text);
        }
    }

    /** Loads a team's descriptor set (what the schema pane's file chooser does with the file chosen). */
    void loadSchema(Path file) {
        model.loadSchema(file);
    }

    @Override
    public Node node() {
        return scroll;
    }

    @Override
    public void refresh(FrameContext frame) {
        ReplayViewModel.Pulled pulled = model.refresh();
        record.refresh();
        if (live.isSelected() != field.liveListening()) {
            live.setSelected(field.liveListening());
        }
        notes.showMessage(model.message());
        schemas.show(model.schemaLines());
        transport.show(model);
        if (pulled == ReplayViewModel.Pulled.NOTHING_WHILE_BUSY) {
            return;
        }
        if (pulled == ReplayViewModel.Pulled.NEW_REPLAY) {
            transport.enable(model.hasReplay());
            picker.show(model.hasReplay(), model.alignedFiles());
        }
        timeline.show(model.state(), model.events());
        notes.showNotes(model.notes());
        setIfChanged(position, model.positionLine());
    }

    @Override
    public void close() {
        model.close();
    }
}
