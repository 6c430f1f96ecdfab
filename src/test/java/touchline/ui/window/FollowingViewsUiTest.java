package touchline.ui.window;

import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.store.StoreEnvelopes;
import touchline.testing.UiTest;
import touchline.ui.consoles.DebugConsoleView;
import touchline.ui.consoles.TextView;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.ViewSource;

/**
 * The views that follow a log (debug console, text view) show each new line once, newest at
 * the bottom, and a search starts again from what the log holds.
 */
@UiTest
class FollowingViewsUiTest {

    private static final int ROBOT = 51;
    @TempDir
    Path layouts;

    /** A console window with no view open and robot {@link #ROBOT} known. */
    private ConsoleWindowFixture window() throws Exception {
        ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts);
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        ui.console.field().bus().accept(StoreEnvelopes.status(ui.console.field().clock().nowMicros(), ROBOT));
        return ui;
    }

    /** Opens the debug console; its list of lines. */
    @SuppressWarnings("unchecked")
    private static ListView<String> debugLines(ConsoleWindowFixture ui) throws Exception {
        ui.fxRun(() -> ui.window.open("debug-console", ViewSource.NONE));
        DebugConsoleView view = ui.view(DebugConsoleView.class);
        return ui.fx(() -> ui.robot.from(view.node()).lookup("#debug-lines").queryAs(ListView.class));
    }

    /** The lines the debug console shows while nobody uses its list, top to bottom, as drawn. */
    private static List<String> newestShown(ConsoleWindowFixture ui) throws Exception {
        DebugConsoleView view = ui.view(DebugConsoleView.class);
        return ui.fx(() -> {
            javafx.scene.Node pane = ui.robot.from(view.node()).lookup("#debug-newest").query();
            if (!pane.isVisible()) {
                return List.<String>of();
            }
            javafx.geometry.Bounds seen = pane.localToScene(pane.getLayoutBounds());
            return ui.robot.from(pane).lookup(".newest-line").queryAllAs(javafx.scene.text.Text.class).stream()
                    .filter(t -> !t.getText().isEmpty() && seen.contains(t.localToScene(t.getLayoutBounds()).getCenterX(),
                            t.localToScene(t.getLayoutBounds()).getCenterY()))
                    .sorted(java.util.Comparator.comparingDouble(t -> t.localToScene(t.getLayoutBounds()).getMinY()))
                    .map(javafx.scene.text.Text::getText).toList();
        });
    }

    /** The bottom one of {@link #newestShown}, or "" when none shows. */
    private static String bottomLine(ConsoleWindowFixture ui) throws Exception {
        List<String> shown = newestShown(ui);
        return shown.isEmpty() ? "" : shown.get(shown.size() - 1);
    }

    /** Gives the window the keyboard and the list the focus: the user tabbed to the list. */
    private static void focus(ConsoleWindowFixture ui, ListView<String> list) throws Exception {
        ui.await(10, () -> ui.fx(() -> list.getScene() != null));
        ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
        ui.fxRun(list::requestFocus);
        ui.await(10, () -> ui.fx(() -> list.getScene().getFocusOwner() == list && list.isFocused()));
    }

    private static void publish(ConsoleWindowFixture ui, String option, String text) {
        ui.console.field().bus().accept(StoreEnvelopes.text(ui.console.field().clock().nowMicros(), ROBOT, option, text));
    }

    @Test
    void theDebugConsoleFollowsTheLogOnceAndSearchRereadsIt() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            followAndSearch(ui);
        }
    }

    private static void followAndSearch(ConsoleWindowFixture ui) throws Exception {
        ListView<String> list = debugLines(ui);
        DebugConsoleView view = ui.view(DebugConsoleView.class);
        publish(ui, "demo.text", "alpha");
        publish(ui, "demo.text", "beta");
        ui.await(10, () -> newestShown(ui).size() == 2);
        publish(ui, "demo.text", "gamma");
        ui.await(10, () -> newestShown(ui).size() == 3);
        long frame = ui.fx(() -> ui.window.pulse().frames());
        ui.await(10, () -> ui.window.pulse().frames() > frame + 5);
        List<String> shown = newestShown(ui);
        assertEquals(3, shown.size(), "each line once: " + shown);
        assertTrue(shown.get(0).endsWith("alpha") && shown.get(2).endsWith("gamma"), "newest at the bottom: " + shown);
        assertEquals(0.0, ui.fx(list::getOpacity), "nobody at the list: the plain lines show in its place");
        ui.fxRun(() -> ui.robot.from(view.node()).lookup("#debug-search").queryAs(TextField.class).setText("beta"));
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == 1);
        assertTrue(ui.fx(() -> list.getItems().get(0).toString()).endsWith("beta"));
        assertEquals(1.0, ui.fx(list::getOpacity), "a search shows the list (its hits highlighted)");
        assertEquals(List.of(), newestShown(ui));
    }

    /**
     * While nobody uses it the list stands still, hidden, and the plain newest lines follow the log; the
     * pointer over it brings the list up at once, holding the same lines, newest at the bottom, and
     * following; when the pointer leaves, the plain lines come back, new lines included.
     */
    @Test
    void theListComesUpAtTheNewestLineWhenThePointerReachesIt() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            ListView<String> list = debugLines(ui);
            for (int i = 1; i <= 40; i++) {
                publish(ui, "demo.text", "line " + i + ".");
            }
            ui.await(10, () -> bottomLine(ui).endsWith("line 40."));
            int before = ui.fx(() -> list.getItems().size());
            publish(ui, "demo.text", "line 41.");
            ui.await(10, () -> bottomLine(ui).endsWith("line 41."));
            assertEquals(before, (int) ui.fx(() -> list.getItems().size()), "the hidden list stands still");

            ui.robot.moveTo(list);
            ui.await(10, () -> ui.fx(list::isHover));
            assertEquals(1.0, ui.fx(list::getOpacity));
            assertTrue(ui.fx(() -> list.getItems().get(list.getItems().size() - 1)).endsWith("line 41."),
                    "the list comes up with every line");
            assertEquals(List.of(), newestShown(ui));
            publish(ui, "demo.text", "line 42.");
            ui.await(10, () -> ui.fx(() -> list.getItems().get(list.getItems().size() - 1)).endsWith("line 42."));

            javafx.scene.Node searchField = ui.robot.from(ui.view(DebugConsoleView.class).node()).lookup("#debug-search").query();
            ui.robot.moveTo(searchField);
            ui.await(10, () -> ui.fx(list::getOpacity) == 0.0);
            publish(ui, "demo.text", "line 43.");
            ui.await(10, () -> bottomLine(ui).endsWith("line 43."));
            List<String> shown = newestShown(ui);
            assertTrue(shown.get(shown.size() - 2).endsWith("line 42."), "the lines in order: " + shown);
        }
    }

    /**
     * The debug console's rows paint no background of their own, only the list does (a scroll fills the
     * list's area once, not again in every row; docs/archive/benchmarks-sessions.md "Seventeenth session"); a selected row
     * still shows its selection.
     */
    @Test
    void theDebugConsolesRowsLeaveTheBackgroundToTheListButShowASelection() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            ListView<String> list = debugLines(ui);
            focus(ui, list);
            for (String t : List.of("alpha", "beta", "gamma")) {
                publish(ui, "demo.text", t);
            }
            ui.await(10, () -> ui.fx(() -> filledRows(list).size()) == 3);
            assertTrue(ui.fx(() -> opaque(list.getBackground())), "the list paints the background: " + ui.fx(list::getBackground));
            assertTrue(ui.fx(() -> filledRows(list).stream().allMatch(c -> c.getBackground() == null && c.getBorder() == null)),
                    "no row paints one of its own");
            ui.fxRun(() -> list.getSelectionModel().select(1));
            ui.await(10, () -> ui.fx(() -> filledRows(list).stream().anyMatch(c -> c.isSelected() && opaque(c.getBackground()))));
            assertTrue(ui.fx(() -> filledRows(list).stream().filter(c -> !c.isSelected()).allMatch(c -> c.getBackground() == null)),
                    "only the selected row is filled");
        }
    }

    private static List<javafx.scene.control.ListCell<?>> filledRows(ListView<?> list) {
        return list.lookupAll(".list-cell").stream()
                .filter(n -> n instanceof javafx.scene.control.ListCell<?> c && !c.isEmpty() && c.isVisible())
                .<javafx.scene.control.ListCell<?>>map(n -> (javafx.scene.control.ListCell<?>) n).toList();
    }

    private static boolean opaque(javafx.scene.layout.Background b) {
        return b != null && b.getFills().stream().anyMatch(f -> f.getFill() instanceof javafx.scene.paint.Color c && c.isOpaque());
    }

    /**
     * Up or Down in a freshly focused list that follows starts at the newest line, the one in view (the
     * list's own keys selected the oldest line it held, out of view, or nothing); the next Up moves to
     * the line above, and the list holds still while a line is selected.
     */
    @Test
    void anArrowKeyInAFollowingListSelectsTheNewestLineAndMovesFromThere() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            ListView<String> list = debugLines(ui);
            int lines = 60; // more than the list shows
            for (int i = 1; i <= lines; i++) {
                publish(ui, "demo.text", "line " + i + ".");
            }
            ui.await(10, () -> bottomLine(ui).endsWith("line " + lines + "."));
            focus(ui, list);
            ui.await(10, () -> ui.fx(() -> list.getItems().size()) == lines);
            ui.robot.type(javafx.scene.input.KeyCode.DOWN);
            ui.await(10, () -> ui.fx(() -> list.getSelectionModel().getSelectedItem()) != null);
            assertTrue(ui.fx(() -> list.getSelectionModel().getSelectedItem()).endsWith("line " + lines + "."),
                    "Down selects the newest line: " + ui.fx(() -> list.getSelectionModel().getSelectedItem()));
            ui.robot.type(javafx.scene.input.KeyCode.UP);
            ui.await(10, () -> ui.fx(() -> list.getSelectionModel().getSelectedItem()).endsWith("line " + (lines - 1) + "."));
            publish(ui, "demo.text", "line " + (lines + 1) + ".");
            ui.await(10, () -> ui.fx(() -> list.getItems().get(list.getItems().size() - 1)).endsWith("line " + (lines + 1) + "."));
            assertTrue(ui.fx(() -> list.getSelectionModel().getSelectedItem()).endsWith("line " + (lines - 1) + "."),
                    "a new line keeps the selection");
            assertEquals(1, (int) ui.fx(() -> list.getSelectionModel().getSelectedItems().size()));
        }
    }

    /**
     * The line Down selects in a following list shows whole, above the list's edge and its sideways scroll
     * bar (lines wider than the list): holding the list still kept its top line in place and could leave the
     * selected newest line half under the bar.
     */
    @Test
    void theNewestLineDownSelectsShowsWhole() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            ListView<String> list = debugLines(ui);
            focus(ui, list);
            String wide = "x".repeat(300);
            int lines = 60;
            for (int i = 1; i <= lines; i++) {
                publish(ui, "demo.text", "line " + i + ". " + wide);
            }
            ui.await(10, () -> ui.fx(() -> list.getItems().size()) == lines);
            ui.robot.type(javafx.scene.input.KeyCode.DOWN);
            ui.await(10, () -> ui.fx(() -> list.getSelectionModel().getSelectedItem()) != null);
            assertTrue(ui.fx(() -> list.getSelectionModel().getSelectedItem()).contains("line " + lines + "."));
            ui.await(10, () -> ui.fx(() -> list.getItems().size()) == lines && ui.fx(() -> wholeInView(list)));
        }
    }

    /** Whether the selected line's row lies whole inside the list's viewport (not under an edge or a scroll bar). */
    private static boolean wholeInView(ListView<String> list) {
        int selected = list.getSelectionModel().getSelectedIndex();
        javafx.scene.Node viewport = list.lookup(".clipped-container");
        for (javafx.scene.Node n : list.lookupAll(".list-cell")) {
            if (n instanceof javafx.scene.control.ListCell<?> c && c.getIndex() == selected && c.isVisible()) {
                javafx.geometry.Bounds row = c.localToScene(c.getLayoutBounds());
                javafx.geometry.Bounds view = viewport.localToScene(viewport.getLayoutBounds());
                return row.getMinY() >= view.getMinY() - 0.5 && row.getMaxY() <= view.getMaxY() + 0.5;
            }
        }
        return false;
    }

    @Test
    void whileFollowingTheListHoldsOnlyTheNewestLinesAndASelectionOrPauseHoldsThemAll() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            tailAndEverything(ui);
        }
    }

    private static void tailAndEverything(ConsoleWindowFixture ui) throws Exception {
        ListView<String> list = debugLines(ui);
        focus(ui, list); // the list follows while the user is at it
        DebugConsoleView view = ui.view(DebugConsoleView.class);
        int lines = 300; // more than the tail (200 to 400 lines), fewer than the console keeps (5 000)
        for (int i = 1; i <= lines; i++) {
            publish(ui, "demo.text", "line " + i + ".");
        }
        ui.await(10, () -> ui.fx(() -> list.getItems().isEmpty() ? "" : list.getItems().get(list.getItems().size() - 1))
                .endsWith("line " + lines + "."));
        int tail = ui.fx(() -> list.getItems().size());
        assertTrue(tail >= 200 && tail <= 300, "following: only the newest lines in the list (200, up to 200 more before a cut): " + tail);
        assertTrue(ui.fx(() -> list.getItems().get(0)).endsWith("line " + (lines - tail + 1) + "."), "the tail is the end of the log");
        ui.await(10, () -> ui.fx(() -> ui.robot.from(view.node()).lookup("#debug-count").queryLabeled().getText())
                .equals(lines + " lines"));

        int line150 = 150 - (lines - tail + 1);
        ui.fxRun(() -> list.getSelectionModel().select(line150)); // "line 150." in the tail
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == lines);
        assertEquals(149, (int) ui.fx(() -> list.getSelectionModel().getSelectedIndex()), "the same line stays selected");
        assertTrue(ui.fx(() -> list.getSelectionModel().getSelectedItem()).endsWith("line 150."));
        publish(ui, "demo.text", "line " + (lines + 1) + ".");
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == lines + 1);
        assertTrue(ui.fx(() -> list.getSelectionModel().getSelectedItem()).endsWith("line 150."), "new lines keep the selection");

        ui.fxRun(() -> list.getSelectionModel().clearSelection());
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == 200);
        assertTrue(ui.fx(() -> list.getItems().get(199)).endsWith("line " + (lines + 1) + "."), "following again, newest last");

        ui.fxRun(() -> ui.robot.from(view.node()).lookup("#debug-pause").queryAs(javafx.scene.control.ToggleButton.class)
                .setSelected(true));
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == lines + 1);
        assertTrue(ui.fx(() -> list.getItems().get(0)).endsWith("line 1."), "paused: every line scrollable");
    }

    @Test
    void theTextViewShowsOnlyItsOptionsLines() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            onlyItsOption(ui);
        }
    }

    /** The lines the text view shows (FX thread). */
    @SuppressWarnings("unchecked")
    private static List<String> shownLines(TextView view) {
        return List.copyOf(((ListView<String>) view.node().lookup("#option-text")).getItems());
    }

    private static void onlyItsOption(ConsoleWindowFixture ui) throws Exception {
        ui.fxRun(() -> ui.window.open("text", new ViewSource(ROBOT, "mine")));
        TextView view = ui.view(TextView.class);
        publish(ui, "mine", "one");
        publish(ui, "other", "not this");
        publish(ui, "mine", "two");
        ui.await(10, () -> ui.fx(() -> shownLines(view)).size() == 2);
        List<String> shown = ui.fx(() -> shownLines(view));
        assertTrue(shown.get(0).endsWith("one") && shown.get(1).endsWith("two"), shown.toString());
    }
}
