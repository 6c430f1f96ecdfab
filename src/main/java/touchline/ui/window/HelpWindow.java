package touchline.ui.window;

import javafx.scene.Scene;
import javafx.scene.control.Label;
import javafx.scene.control.TextArea;
import javafx.scene.input.KeyCode;
import javafx.scene.layout.BorderPane;
import javafx.stage.Stage;
import javafx.stage.Window;

/**
 * A help text in a window of its own: the focused view's help (F1), the keyboard shortcuts
 * (Ctrl+/) or every view's. Scrollable, selectable, closed with Esc.
 */
final class HelpWindow {

    /** The start of every help window's title. */
    static final String TITLE = "Help — ";
    private final WindowPlaces places;

    HelpWindow(WindowPlaces places) {
        this.places = places;
    }

    /** The help of one registry entry, with the keys its view answers to. */
    static String text(ViewSpec spec, Shortcuts shortcuts) {
        StringBuilder s = new StringBuilder(spec.help()).append("\n");
        var keys = shortcuts.forView(spec.id());
        if (!keys.isEmpty()) {
            s.append("\nKeys in this view:\n");
            keys.forEach(k -> s.append(k.line()).append('\n'));
        }
        s.append("\nF1: this help   Ctrl+/: every keyboard shortcut   Ctrl+K: open any view");
        return s.toString();
    }

    Stage show(Window owner, String title, String body) {
        Stage stage = new Stage();
        stage.initOwner(owner);
        stage.setTitle(TITLE + title);
        Label heading = new Label(title);
        heading.setId("help-title");
        heading.setStyle("-fx-font-size: 1.3em; -fx-font-weight: bold; -fx-padding: 8 8 4 8;");
        TextArea text = new TextArea(body);
        text.setId("help-text");
        text.setEditable(false);
        text.setWrapText(true);
        text.setStyle("-fx-font-family: monospace;");
        BorderPane root = new BorderPane(text);
        root.setTop(heading);
        Scene scene = new Scene(root);
        if (owner != null && owner.getScene() != null) {
            scene.getStylesheets().addAll(owner.getScene().getStylesheets());
        }
        CloseAfterKey closer = new CloseAfterKey(stage);
        scene.addEventFilter(javafx.scene.input.KeyEvent.KEY_PRESSED, e -> {
            if (e.getCode() == KeyCode.ESCAPE) {
                closer.close();
                e.consume();
            }
        });
        stage.setScene(scene);
        places.keep(stage, "help", 760, 560);
        stage.show();
        text.requestFocus();
        return stage;
    }
}
