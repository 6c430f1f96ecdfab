package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.TextField;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.VBox;
import javafx.stage.FileChooser;
import touchline.app.Recordings;
import touchline.record.RecorderStats;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Start and stop recording everything the console sees (live and replayed, in and out) to an
 * MCAP file, with the recorder's counters and its failure, if writing failed. Opening and
 * closing the file happen on the view's background thread (closing writes the index).
 */
final class RecordPanel {

    private final Recordings recordings;
    private final WorkQueue work;
    private final RecordingName name;
    private final TextField path = new TextField();
    private final Button toggle = new Button("Start recording");
    private final Label counters = new Label("Not recording.");
    private final Label failure = new Label();
    private final VBox root;
    private RecorderStats last;
    private boolean recording;

    RecordPanel(Recordings recordings, touchline.transport.MicrosClock clock, WorkQueue work) {
        this.recordings = recordings;
        this.work = work;
        path.setId("record-path");
        this.name = new RecordingName(clock, java.time.ZoneId.systemDefault());
        path.setText(name.offer());
        toggle.setId("record-toggle");
        counters.setId("record-counters");
        failure.setId("record-failure");
        failure.setStyle("-fx-text-fill: #cf222e;");
        failure.setWrapText(true);
        failure.managedProperty().bind(failure.textProperty().isNotEmpty());
        Button browse = new Button("Browse…");
        browse.setOnAction(e -> browse());
        toggle.setOnAction(e -> toggle());
        HBox.setHgrow(path, Priority.ALWAYS);
        HBox row = new HBox(8, new Label("File"), path, browse, toggle);
        row.setStyle("-fx-alignment: center-left;");
        Label title = new Label("Record");
        title.setStyle("-fx-font-weight: bold;");
        root = new VBox(6, title, row, counters, failure);
    }

    Node node() {
        return root;
    }

    private void browse() {
        FileChooser chooser = new FileChooser();
        chooser.setTitle("Record to");
        chooser.getExtensionFilters().add(new FileChooser.ExtensionFilter("MCAP recordings", "*.mcap"));
        Path current = Path.of(path.getText()).toAbsolutePath();
        if (Files.isDirectory(current.getParent())) {
            chooser.setInitialDirectory(current.getParent().toFile());
        }
        chooser.setInitialFileName(current.getFileName().toString());
        javafx.stage.Window window = root.getScene().getWindow();
        java.io.File f = new touchline.ui.window.StaysMaximised(window).during(() -> chooser.showSaveDialog(window));
        if (f != null) {
            path.setText(f.toString());
        }
    }

    private void toggle() {
        failure.setText("");
        if (recording) {
            toggle.setDisable(true);
            work.run(() -> {
                try {
                    recordings.stop();
                } catch (IOException e) {
                    work.handOff(() -> failure.setText("Finishing the recording failed: " + e.getMessage()));
                }
            });
            return;
        }
        Path file = name.forStart(path.getText());
        toggle.setDisable(true);
        work.run(() -> {
            try {
                Path parent = file.toAbsolutePath().getParent();
                if (parent != null) {
                    Files.createDirectories(parent);
                }
                recordings.start(file);
            } catch (IOException | RuntimeException e) {
                work.handOff(() -> failure.setText("Cannot record to " + file + ": " + e.getMessage()));
            }
        });
    }

    /** Pulls the recorder's counters; only when no file operation holds the console. */
    void refresh() {
        if (work.busy()) {
            return;
        }
        toggle.setDisable(false);
        RecorderStats s = recordings.current().orElse(null);
        boolean now = s != null;
        if (now != recording) {
            recording = now;
            toggle.setText(now ? "Stop recording" : "Start recording");
            path.setDisable(now);
            if (!now) {
                path.setText(name.offer()); // the next recording must not overwrite this one
            }
        }
        if (s != null) {
            last = s;
        }
        String text = last == null ? "Not recording." : (now ? "Recording: " : "Stopped: ") + counters(last);
        if (!text.equals(counters.getText())) {
            counters.setText(text);
        }
        if (last != null && last.failure() != null && !failure.getText().contains(last.failure())) {
            failure.setText("Recording failed: " + last.failure());
        }
    }

    static String counters(RecorderStats s) {
        String files = s.files().isEmpty() ? "–" : s.files().get(s.files().size() - 1).toString()
                + (s.files().size() > 1 ? " (" + s.files().size() + " files)" : "");
        return String.format(Locale.ROOT, "%,d written, %,d dropped, %s — %s", s.written(), s.dropped(),
                bytes(s.bytes()), files);
    }

    static String bytes(long n) {
        return n < 1024 ? n + " B" : n < 1 << 20 ? String.format(Locale.ROOT, "%.1f KiB", n / 1024.0)
                : String.format(Locale.ROOT, "%.1f MiB", n / (double) (1 << 20));
    }
}
