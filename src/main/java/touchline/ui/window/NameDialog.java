package touchline.ui.window;

import javafx.scene.control.TextInputDialog;
import javafx.scene.layout.Region;
import javafx.stage.Stage;

import java.util.Optional;
import java.util.function.Consumer;

/**
 * Asks for a name (saving or renaming a layout): a small dialog owned by the window, not modal, placed where
 * it was last, and never smaller than its own content, so its buttons are never cut off whatever
 * size was remembered or the font asks for.
 */
final class NameDialog {

    private final TextInputDialog dialog;

    NameDialog(Stage owner, WindowPlaces places, String title, String question, String suggested) {
        dialog = new TextInputDialog(suggested);
        dialog.initOwner(owner);
        // not modal: under a window manager a modal dialog takes a maximised window out of its
        // maximised state (openbox, GTK); this one leaves the window as it is (SaveAsDialog too)
        dialog.initModality(javafx.stage.Modality.NONE);
        dialog.setTitle(title);
        dialog.setHeaderText(question);
        dialog.getDialogPane().setMinHeight(Region.USE_PREF_SIZE);
        dialog.getDialogPane().setMinWidth(Region.USE_PREF_SIZE);
        Stage stage = (Stage) dialog.getDialogPane().getScene().getWindow();
        places.keep(stage, "name-dialog", 460, 260);
        // a remembered or window-manager size smaller than the content grows to it once shown
        stage.setOnShown(e -> {
            javafx.scene.control.DialogPane pane = dialog.getDialogPane();
            if (pane.getWidth() + 0.5 < pane.prefWidth(-1) || pane.getHeight() + 0.5 < pane.prefHeight(pane.getWidth())) {
                stage.sizeToScene();
            }
        });
    }

    /** Shows it without blocking; {@code onName} gets the name given, stripped, when OK closes it (not on Cancel or blank). */
    void ask(Consumer<String> onName) {
        dialog.setOnHidden(e -> Optional.ofNullable(dialog.getResult()).map(String::strip).filter(n -> !n.isEmpty())
                .ifPresent(onName));
        dialog.show();
    }
}
