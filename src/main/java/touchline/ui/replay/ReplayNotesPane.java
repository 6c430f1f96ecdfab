package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.VBox;
import touchline.record.ReplayNotes;

import java.util.List;

/**
 * What the replay says about itself: the message line (what happened last; red for a failure),
 * and what was skipped, said as {@code replay} says it: a badge, its tooltip and the list below it.
 */
final class ReplayNotesPane {

    private final Label message = new Label();
    private final ListView<String> problems = new ListView<>();
    private final Label badge = new Label();
    private final Tooltip tip = new Tooltip();
    private final VBox pane;
    private ReplayNotes shown = ReplayNotes.NONE;

    ReplayNotesPane() {
        message.setId("replay-message");
        message.setWrapText(true);
        problems.setId("replay-problems");
        problems.setPrefHeight(60);
        problems.setVisible(false);
        problems.setManaged(false);
        badge.setId("replay-notes");
        badge.setWrapText(true);
        badge.setStyle("-fx-text-fill: #9a6700; -fx-font-weight: bold;");
        badge.setTooltip(tip);
        badge.managedProperty().bind(badge.textProperty().isNotEmpty());
        badge.visibleProperty().bind(badge.textProperty().isNotEmpty());
        pane = new VBox(6, message, badge, problems);
    }

    Node node() {
        return pane;
    }

    void showMessage(ReplayViewModel.Message m) {
        ReplayView.setIfChanged(message, m.text());
        message.setStyle(m.failure() ? "-fx-text-fill: #cf222e;" : "");
    }

    /** Shows the notes; the list is rebuilt only when they changed. */
    void showNotes(ReplayNotes notes) {
        if (notes.equals(shown)) {
            return;
        }
        shown = notes;
        List<String> items = ReplayViewModel.noteLines(notes);
        problems.getItems().setAll(items);
        problems.setVisible(!items.isEmpty());
        problems.setManaged(!items.isEmpty());
        badge.setText(notes.badge());
        tip.setText(String.join("\n", notes.lines()));
    }
}
