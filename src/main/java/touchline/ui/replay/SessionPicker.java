package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.TextField;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.VBox;
import javafx.stage.FileChooser;
import javafx.stage.Window;
import touchline.ui.window.StaysMaximised;

import java.io.File;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Which recording(s) to replay: the path field (several files separated by {@code ;}, each with
 * an optional clock offset), Browse, Open, Add file and Close replay, and, for a session of
 * several files, how each file's clock was moved onto the first one's.
 */
final class SessionPicker {

    private final ReplayViewModel model;
    private final TextField path = new TextField();
    private final Button close;
    private final Label files = new Label();
    private final VBox pane;

    SessionPicker(ReplayViewModel model) {
        this.model = model;
        path.setId("replay-path");
        path.setPromptText("recording.mcap  (several: laptop.mcap; robot3.mcap or robot3.mcap=+1.250 with its clock offset)");
        path.setOnAction(e -> model.open(path.getText()));
        HBox.setHgrow(path, Priority.ALWAYS);
        // the path on a row of its own: beside four buttons it shrank to nothing in the demo layout's
        // left pane at 1280 px (the "File" label cut to "…")
        path.setMinWidth(160);
        Button browse = new Button("Browse…");
        browse.setOnAction(e -> browse());
        Button open = ReplayView.button("replay-open", "Open", () -> model.open(path.getText()));
        Button add = ReplayView.button("replay-add", "Add file…", this::addFiles);
        close = ReplayView.button("replay-close", "Close replay", model::closeReplay);
        files.setId("replay-files");
        files.setWrapText(true);
        files.setVisible(false);
        files.setManaged(false);
        pane = new VBox(6, ReplayView.row(new Label("File"), path), ReplayView.row(browse, open, add, close));
    }

    /** The path field and its buttons. */
    Node node() {
        return pane;
    }

    /** The aligned files' lines (shown under the timeline). */
    Node files() {
        return files;
    }

    /** A replay opened or closed: Close rests without one, the aligned files are the new session's. */
    void show(boolean replayOpen, List<String> aligned) {
        close.setDisable(!replayOpen);
        files.setText(String.join("\n", aligned));
        files.setTooltip(aligned.isEmpty() ? null : new Tooltip(
                "Each file's clock moved onto the first file's: by the GameController packets both heard "
                        + "(median difference; 'agree within' = 95% of them), or by the offset given as file=+seconds"));
        files.setVisible(!aligned.isEmpty());
        files.setManaged(!aligned.isEmpty());
    }

    /** Chooses one or several recordings (several play as one session) and opens them. */
    private void browse() {
        List<Path> chosen = choose("Open recording(s)");
        if (!chosen.isEmpty()) {
            path.setText(new SessionFiles(chosen, Map.of()).text());
            model.open(path.getText());
        }
    }

    /** Adds recordings to the files in the field (the open session) and opens them all as one session. */
    private void addFiles() {
        List<Path> chosen = choose("Add recording(s) to the session");
        if (!chosen.isEmpty()) {
            path.setText(SessionFiles.parse(path.getText()).plus(chosen).text());
            model.open(path.getText());
        }
    }

    private List<Path> choose(String title) {
        FileChooser chooser = new FileChooser();
        chooser.setTitle(title);
        chooser.getExtensionFilters().addAll(new FileChooser.ExtensionFilter("MCAP recordings", "*.mcap"),
                new FileChooser.ExtensionFilter("All files", "*"));
        Window window = pane.getScene().getWindow();
        List<File> f = new StaysMaximised(window).during(() -> chooser.showOpenMultipleDialog(window));
        return f == null ? List.of() : f.stream().map(File::toPath).toList();
    }
}
