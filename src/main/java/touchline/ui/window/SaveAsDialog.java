package touchline.ui.window;

import javafx.scene.control.TextInputDialog;
import javafx.scene.layout.Region;
import javafx.stage.Modality;
import javafx.stage.Window;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * Asks where to save a file: a JavaFX dialog owned by the window and not modal. Under a window
 * manager (openbox, GTK) a native file chooser and a modal dialog both take the main window
 * out of its maximised state; a dialog that leaves the window enabled does not. The answer
 * comes back on the FX thread once the dialog is closed with OK; a name that is no path is
 * said in the dialog, which stays open.
 */
public final class SaveAsDialog {

    private final TextInputDialog dialog;

    public SaveAsDialog(Window owner, String title, Path suggested) {
        dialog = new TextInputDialog(suggested.toString());
        dialog.initOwner(owner);
        dialog.initModality(Modality.NONE);
        dialog.setTitle(title);
        dialog.setHeaderText("File to write (its folder must exist)");
        dialog.getEditor().setPrefColumnCount(40);
        dialog.getDialogPane().setMinHeight(Region.USE_PREF_SIZE);
        dialog.getDialogPane().setMinWidth(Region.USE_PREF_SIZE);
        javafx.scene.control.Button ok = (javafx.scene.control.Button) dialog.getDialogPane()
                .lookupButton(javafx.scene.control.ButtonType.OK);
        ok.addEventFilter(javafx.event.ActionEvent.ACTION, e -> {
            try {
                Path.of(dialog.getEditor().getText().strip());
            } catch (InvalidPathException bad) {
                dialog.setHeaderText("Not a file name: " + bad.getMessage());
                e.consume();
            }
        });
    }

    /** Shows it without blocking; {@code onChosen} gets the path given when OK closes it (nothing on Cancel). */
    public void ask(Consumer<Path> onChosen) {
        dialog.setOnHidden(e -> {
            String text = dialog.getResult();
            if (text != null && !text.isBlank()) {
                onChosen.accept(Path.of(text.strip()));
            }
        });
        dialog.show();
    }
}
