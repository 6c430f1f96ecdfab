package touchline.ui.window;

import javafx.scene.control.Alert;
import javafx.scene.control.ButtonType;
import javafx.scene.layout.Region;
import javafx.stage.Modality;
import javafx.stage.Stage;

/**
 * Asks OK or Cancel before something that cannot be undone (deleting a layout): owned by the
 * window and not modal, like {@link NameDialog}, so a maximised window stays maximised under a
 * window manager; placed where it was last and never smaller than its own content.
 */
final class ConfirmDialog {

    private final Alert alert;

    ConfirmDialog(Stage owner, WindowPlaces places, String title, String question) {
        alert = new Alert(Alert.AlertType.CONFIRMATION, question, ButtonType.OK, ButtonType.CANCEL);
        alert.initOwner(owner);
        // a modal dialog takes a maximised window out of its maximised state (openbox, GTK)
        alert.initModality(Modality.NONE);
        alert.setTitle(title);
        alert.setHeaderText(null);
        alert.getDialogPane().setMinHeight(Region.USE_PREF_SIZE);
        alert.getDialogPane().setMinWidth(Region.USE_PREF_SIZE);
        Stage stage = (Stage) alert.getDialogPane().getScene().getWindow();
        places.keep(stage, "confirm-dialog", 520, 200);
        stage.setOnShown(e -> {
            javafx.scene.control.DialogPane pane = alert.getDialogPane();
            if (pane.getWidth() + 0.5 < pane.prefWidth(-1) || pane.getHeight() + 0.5 < pane.prefHeight(pane.getWidth())) {
                stage.sizeToScene();
            }
        });
    }

    /** Shows it without blocking; {@code onOk} runs when OK closes it (not on Cancel or the window's close). */
    void ask(Runnable onOk) {
        alert.setOnHidden(e -> {
            if (alert.getResult() == ButtonType.OK) {
                onOk.run();
            }
        });
        alert.show();
    }
}
