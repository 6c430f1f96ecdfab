package touchline.ui.window;

import javafx.scene.Node;
import javafx.scene.control.Alert;
import javafx.scene.control.Label;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuItem;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyCodeCombination;
import javafx.scene.input.KeyCombination;
import javafx.scene.input.KeyEvent;
import javafx.stage.Stage;
import javafx.stage.Window;
import touchline.app.RuntimeReport;

import java.util.Optional;
import java.util.function.Supplier;

/**
 * The window's Help menu and F1: the help of the view that has the keyboard (in the main window or
 * any the console opened), the keyboard shortcut sheet, every view's help, and About Touchline.
 */
final class HelpMenu {

    private final HelpWindow help;
    private final Shell shell;
    private final ViewContext context;
    private final WindowPlaces places;
    private final Supplier<Stage> stage;
    private final Supplier<Shortcuts> shortcuts;
    private final Menu menu = new Menu("_Help");

    /** {@code stage} gives the main window once shown; {@code shortcuts} the menus' shortcuts once built. */
    HelpMenu(Shell shell, ViewContext context, WindowPlaces places, Supplier<Stage> stage, Supplier<Shortcuts> shortcuts) {
        this.help = new HelpWindow(places);
        this.shell = shell;
        this.context = context;
        this.places = places;
        this.stage = stage;
        this.shortcuts = shortcuts;
        MenuItem forView = new MenuItem("Help for this _view");
        forView.setAccelerator(new KeyCodeCombination(KeyCode.F1));
        forView.setOnAction(e -> forFocusedView());
        MenuItem keys = new MenuItem("_Keyboard shortcuts");
        keys.setAccelerator(new KeyCodeCombination(KeyCode.SLASH, KeyCombination.SHORTCUT_DOWN));
        keys.setOnAction(e -> shortcutSheet());
        MenuItem about = new MenuItem("_Views…");
        about.setOnAction(e -> forViews(stage.get()));
        MenuItem aboutTouchline = new MenuItem("_About Touchline…");
        aboutTouchline.setId("help-about");
        aboutTouchline.setOnAction(e -> about());
        menu.getItems().addAll(forView, keys, about, aboutTouchline);
    }

    Menu menu() {
        return menu;
    }

    /** F1: the help of the view that has the keyboard (every view's when none has). */
    Stage forFocusedView() {
        Stage s = stage.get();
        return helpFor(s.getScene().getFocusOwner(), s); // a menu item of the shown window: both exist
    }

    /** Help → Keyboard shortcuts (Ctrl+/): the sheet, read from the menus' accelerators. */
    Stage shortcutSheet() {
        return help.show(stage.get(), "Keyboard shortcuts", shortcuts.get().sheet(context.registry()));
    }

    /**
     * F1 in a window other than the main one (whose menu answers it): a view dragged out into its
     * own window gives its help, Ctrl+K and the dialogs every view's.
     */
    void key(KeyEvent e, Window w) {
        if (e.getCode() != KeyCode.F1 || w == stage.get() || w == null
                || (w instanceof Stage s && s.getTitle() != null && s.getTitle().startsWith(HelpWindow.TITLE))) {
            return;
        }
        e.consume();
        helpFor(w.getScene().getFocusOwner(), w);
    }

    private Stage helpFor(Node focused, Window owner) {
        Optional<Shell.OpenView> view = shell.containing(focused);
        if (view.isPresent()) {
            ViewSpec spec = view.get().spec();
            return help.show(owner, spec.title(), HelpWindow.text(spec, shortcuts.get()));
        }
        return forViews(owner);
    }

    private Stage forViews(Window owner) {
        StringBuilder s = new StringBuilder();
        for (ViewSpec v : context.registry().all()) {
            s.append(v.title()).append(": ").append(v.help()).append("\n\n");
        }
        s.append("Ctrl+K opens any view. F1 gives the help of the view that has the keyboard, Ctrl+/ every "
                + "shortcut. Drag a tab to split or move it, or out of the window.");
        return help.show(owner, "Views", s.toString());
    }

    private void about() {
        RuntimeReport report = context.field().runtime();
        Alert a = new Alert(Alert.AlertType.INFORMATION);
        a.initOwner(stage.get());
        a.setTitle("About Touchline");
        a.setHeaderText(report.version().title());
        Label text = new Label(String.join("\n", report.lines().subList(1, report.lines().size())));
        text.setId("help-about-text");
        text.setWrapText(true);
        a.getDialogPane().setContent(text);
        a.setResizable(true);
        places.keep((Stage) a.getDialogPane().getScene().getWindow(), "about", 560, 260);
        a.show();
    }
}
