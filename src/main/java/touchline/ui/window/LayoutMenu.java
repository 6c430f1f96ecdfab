package touchline.ui.window;

import javafx.scene.control.Alert;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuItem;
import javafx.scene.control.SeparatorMenuItem;
import javafx.stage.Stage;

import java.io.IOException;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * The window's Layout menu: save the open views under a name, the default layout, rename or delete
 * a saved one (asked in a dialog, answered on the status line) and open each saved layout; also the
 * quiet "last" layout the window reads when it opens and writes when it closes.
 */
final class LayoutMenu {

    /** Save, Default, Rename, Delete and a separator: the saved layouts follow them. */
    private static final int FIXED = 5;
    private final LayoutStore layouts;
    private final Shell shell;
    private final StatusBar status;
    private final WindowPlaces places;
    private final Supplier<Stage> stage;
    private final Menu menu = new Menu("_Layout");
    private final Menu renameMenu = new Menu("_Rename layout");
    private final Menu deleteMenu = new Menu("De_lete layout");

    /** {@code stage} gives the window once it is shown: the dialogs' owner. */
    LayoutMenu(LayoutStore layouts, Shell shell, StatusBar status, WindowPlaces places, Supplier<Stage> stage) {
        this.layouts = layouts;
        this.shell = shell;
        this.status = status;
        this.places = places;
        this.stage = stage;
        MenuItem save = new MenuItem("_Save layout as…");
        save.setOnAction(e -> new NameDialog(stage.get(), places, "Save layout", "Name of the layout", "my layout").ask(
                name -> {
                    try {
                        save(name);
                    } catch (IOException ex) {
                        new Alert(Alert.AlertType.ERROR, "Could not save: " + ex.getMessage()).show();
                    }
                }));
        MenuItem demo = new MenuItem("_Default layout");
        demo.setOnAction(e -> shell.restore(DemoLayout.standard()));
        renameMenu.setId("menu-rename-layout");
        deleteMenu.setId("menu-delete-layout");
        menu.getItems().addAll(save, demo, renameMenu, deleteMenu, new SeparatorMenuItem());
        menu.setOnShowing(e -> rebuild());
        rebuild();
    }

    Menu menu() {
        return menu;
    }

    void save(String name) throws IOException {
        layouts.save(name, shell.capture());
        status.say("layout \"" + name + "\" saved in " + layouts.dir());
        rebuild();
    }

    /** Renames a saved layout; the status line says what happened or why not. */
    void rename(String from, String to) {
        try {
            layouts.rename(from, to);
            status.say("layout \"" + from + "\" is now \"" + to + "\"");
        } catch (IOException e) {
            status.say("could not rename layout \"" + from + "\": " + e.getMessage());
        }
        rebuild();
    }

    /** Deletes a saved layout; the status line says so. */
    void delete(String name) {
        try {
            status.say(layouts.delete(name) ? "layout \"" + name + "\" deleted" : "no layout \"" + name + "\"");
        } catch (IOException e) {
            status.say("could not delete layout \"" + name + "\": " + e.getMessage());
        }
        rebuild();
    }

    boolean load(String name) throws IOException {
        Optional<List<LayoutNode>> l = layouts.load(name);
        l.ifPresent(shell::restore);
        status.say(l.isPresent() ? "layout \"" + name + "\" restored" : "no layout \"" + name + "\"");
        return l.isPresent();
    }

    /** The saved layout {@code name} if it can be read and has views; nothing said. */
    Optional<List<LayoutNode>> loadQuietly(String name) {
        try {
            return layouts.load(name).filter(w -> !w.isEmpty());
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    /** Saves the open views as {@code name}; a failure is logged, not shown (the window is closing). */
    void saveQuietly(String name) {
        try {
            layouts.save(name, shell.capture());
        } catch (IOException e) {
            org.slf4j.LoggerFactory.getLogger(ConsoleWindow.class).warn("could not save layout: {}", e.toString());
        }
    }

    private void rebuild() {
        menu.getItems().remove(FIXED, menu.getItems().size());
        renameMenu.getItems().clear();
        deleteMenu.getItems().clear();
        renameMenu.setDisable(layouts.names().isEmpty()); // nothing saved yet: nothing to rename or delete
        deleteMenu.setDisable(layouts.names().isEmpty());
        for (String name : layouts.names()) {
            MenuItem rename = new MenuItem("\"" + name + "\"…");
            rename.setOnAction(e -> new NameDialog(stage.get(), places, "Rename layout", "New name of \"" + name + "\"", name)
                    .ask(to -> {
                        if (!to.equals(name)) {
                            rename(name, to);
                        }
                    }));
            renameMenu.getItems().add(rename);
            MenuItem delete = new MenuItem("\"" + name + "\"…");
            delete.setOnAction(e -> confirmDelete(name));
            deleteMenu.getItems().add(delete);
            MenuItem item = new MenuItem("Open \"" + name + "\"");
            item.setOnAction(e -> {
                try {
                    load(name);
                } catch (IOException ex) {
                    status.say("could not read layout " + name + ": " + ex.getMessage());
                }
            });
            menu.getItems().add(item);
        }
    }

    private void confirmDelete(String name) {
        new ConfirmDialog(stage.get(), places, "Delete layout", "Delete the layout \"" + name + "\"? Its file in "
                + layouts.dir() + " is removed.").ask(() -> delete(name));
    }
}
