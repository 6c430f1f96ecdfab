package touchline.ui.window;

import javafx.scene.control.ListView;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.TableView;
import javafx.scene.control.TextArea;
import javafx.scene.control.TreeView;
import javafx.scene.input.KeyCode;
import javafx.scene.layout.BorderStroke;
import javafx.stage.Stage;
import javafx.stage.Window;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.RobotProcess;
import touchline.testing.UiTest;
import touchline.transport.Envelope;
import touchline.ui.window.LayoutNode;

import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;
import touchline.ui.frame.ViewSource;

/**
 * Issue #14's keyboard and help items in the real window (headless): F1 gives the focused
 * view's help from the registry and Esc closes it; the shortcut sheet is read from the menus'
 * accelerators; every menu has a mnemonic; the focused control is ringed; Space works in the
 * options tree after coming back to its tab and a click on a row's box toggles it; the debug
 * console highlights matches, counts what arrives while paused and says what Copy copied; the
 * network console keeps the selected row in view while the oldest rows go, starts Down at its newest row and shows ASCII
 * beside the hex.
 */
@UiTest
@Tag("integration")
class KeyboardUiTest {

    private ConsoleWindowFixture ui;

    /** The first control each view under test shows: a restored view joins the scene a pulse later. */
    private static final java.util.Map<String, String> FIRST_CONTROL = java.util.Map.of(
            "network", "#network-table", "debug-console", "#debug-lines", "options", "#options-tree");

    private void only(String viewId) throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry(viewId, ""))))));
        String control = FIRST_CONTROL.get(viewId);
        // (soak run beside two hogs: the lookup right after the restore found no #network-table yet)
        ui.await(30, () -> ui.robot.lookup(control).tryQuery().map(n -> n.getScene() != null).orElse(false));
    }

    private Optional<Stage> helpWindow() {
        return Window.getWindows().stream().filter(w -> w instanceof Stage s && s.getTitle() != null
                && s.getTitle().startsWith("Help — ") && s.isShowing()).map(w -> (Stage) w).findFirst();
    }

    private String helpText() throws Exception {
        return ui.fx(() -> ((TextArea) helpWindow().orElseThrow().getScene().lookup("#help-text")).getText());
    }

    @Test
    void f1OpensTheHelpOfTheFocusedViewFromTheRegistryAndEscClosesIt() throws Exception {
        only("network");
        ui.await(10, () -> ui.robot.lookup("#network-table").tryQuery().isPresent());
        ui.fxRun(() -> {
            ui.window.scene().getWindow().requestFocus();
            ui.robot.lookup("#network-table").query().requestFocus();
        });
        ui.await(10, () -> ui.window.scene().getFocusOwner() == ui.robot.lookup("#network-table").query());
        ui.robot.type(KeyCode.F1);
        ui.await(10, () -> helpWindow().isPresent());
        String spec = ui.window.registry().byId("network").orElseThrow().help();
        assertTrue(helpText().contains(spec), helpText());
        assertEquals("Help — Network console", ui.fx(() -> helpWindow().orElseThrow().getTitle()));
        ui.await(10, () -> helpWindow().orElseThrow().isFocused());
        ui.robot.type(KeyCode.ESCAPE);
        ui.await(10, () -> helpWindow().isEmpty());
    }

    @Test
    void theShortcutSheetListsTheMenusAcceleratorsAndMnemonics() throws Exception {
        MenuBar bar = ui.fx(() -> (MenuBar) ui.window.scene().lookup(".menu-bar"));
        for (Menu m : bar.getMenus()) {
            assertTrue(m.isMnemonicParsing() && m.getText().contains("_"), "no mnemonic: " + m.getText());
        }
        ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
        ui.robot.press(KeyCode.CONTROL).type(KeyCode.SLASH).release(KeyCode.CONTROL);
        ui.await(10, () -> helpWindow().isPresent());
        String sheet = helpText();
        assertTrue(sheet.contains("Ctrl+K") && sheet.contains("Quick open"), sheet);
        assertTrue(sheet.contains("F1") && sheet.contains("Help for this view"), sheet);
        assertTrue(sheet.contains("Alt+V") && sheet.contains("the View menu"), sheet);
        assertTrue(sheet.contains("Space") && sheet.contains("Debug options"), sheet);
        // the referee's keys, each with what it does (issue 36)
        String referee = sheet.substring(sheet.indexOf("\nGameController\n"));
        for (String key : List.of("Space", "R", "S", "P", "B", "D", "A", "Esc", "Ctrl+Z")) {
            assertTrue(referee.lines().anyMatch(l -> l.trim().startsWith(key + " ")), key + " missing:\n" + referee);
        }
    }

    @Test
    void f1InTheGameControllerTabListsTheRefereesKeys() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                List.of(new LayoutNode.Entry("gamecontroller", ""))))));
        ui.await(30, () -> ui.robot.lookup("#gc-start").tryQuery().map(n -> n.getScene() != null).orElse(false));
        ui.fxRun(() -> {
            ui.window.scene().getWindow().requestFocus();
            ui.robot.lookup("#gc-start").query().requestFocus();
        });
        ui.await(30, () -> ui.window.scene().getFocusOwner() == ui.robot.lookup("#gc-start").query());
        ui.robot.type(KeyCode.F1);
        ui.await(30, () -> helpWindow().isPresent());
        String help = helpText();
        assertTrue(help.contains("stop or resume play") && help.contains("Ready") && help.contains("dropped ball")
                && help.contains("+1 minute") && help.contains("forget the call"), help);
    }

    @Test
    void theFocusedControlIsRinged() throws Exception {
        only("debug-console");
        ui.await(10, () -> ui.robot.lookup("#debug-lines").tryQuery().isPresent());
        ui.fxRun(() -> ui.robot.lookup("#debug-search").query().requestFocus());
        ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
        ui.await(10, () -> ui.robot.lookup("#debug-search").query().isFocused());
        ui.await(10, () -> ring(ui.robot.lookup("#debug-search").query()) >= 2
                && ring(ui.robot.lookup("#debug-lines").query()) < 2);
        ui.fxRun(() -> ui.robot.lookup("#debug-lines").query().requestFocus());
        ui.await(10, () -> ring(ui.robot.lookup("#debug-lines").query()) >= 2
                && ring(ui.robot.lookup("#debug-search").query()) < 2);
    }

    /** The width of the focus ring around a control (0: none). */
    private static double ring(javafx.scene.Node n) {
        var border = ((javafx.scene.layout.Region) n).getBorder();
        if (border == null || border.getStrokes().isEmpty()) {
            return 0;
        }
        BorderStroke s = border.getStrokes().get(0);
        return s.getTopStroke() instanceof javafx.scene.paint.Color c && c.getOpacity() > 0 ? s.getWidths().getTop() : 0;
    }

    @Test
    @SuppressWarnings("unchecked")
    void spaceWorksAfterComingBackToTheOptionsTabAndTheBoxToggles() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(3, ui.port()).start()) {
            only("options");
            ui.selectOption(3, "demo.text");
            ui.fxRun(() -> ui.window.open("network", ViewSource.NONE)); // another tab in front
            ui.await(10, () -> ui.robot.lookup("#network-table").tryQuery().map(n -> n.getScene() != null).orElse(false));
            ui.fxRun(() -> ui.robot.lookup("#network-table").query().requestFocus());
            ui.fxRun(() -> ui.window.open("options", ViewSource.NONE)); // back
            ui.await(10, () -> ui.window.scene().getFocusOwner() instanceof TreeView<?>);
            ui.robot.type(KeyCode.SPACE);
            ui.await(10, () -> ui.console.field().options().options(3).option("demo.text").orElseThrow().wanted());

            ui.await(10, () -> ui.optionCell(3, "demo.plotter") != null);
            ui.robot.clickOn(ui.fx(() -> ui.optionCell(3, "demo.plotter").lookup(".option-box")));
            ui.await(10, () -> ui.console.field().options().options(3).option("demo.plotter").orElseThrow().wanted());
            ui.await(10, () -> ((javafx.scene.control.CheckBox) ui.optionCell(3, "demo.plotter").lookup(".option-box"))
                    .isSelected());
        }
    }

    @Test
    @SuppressWarnings("unchecked")
    void theDebugConsoleHighlightsCountsWhilePausedAndSaysWhatItCopied() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(4, ui.port(), "--rate", "50").start()) {
            only("debug-console");
            ui.await(15, () -> ui.console.field().options().options(4).listReceived());
            ui.console.optionSwitches().set(4, "demo.text", true);
            ui.await(10, () -> counted("") > 5); // "N lines"

            ui.fxRun(() -> ui.robot.lookup("#debug-search").queryTextInputControl().setText("BALL AT"));
            ui.await(10, () -> ui.robot.lookup(".search-hit").queryAll().stream()
                    .anyMatch(n -> ((javafx.scene.control.Label) n).getText().equals("ball at")));

            ui.fxRun(() -> ui.robot.lookup("#debug-pause").queryAs(javafx.scene.control.ToggleButton.class).setSelected(true));
            ui.await(10, () -> counted("paused — ") >= 10);

            // copied while still paused: the list stands still, so the selected line stays selected
            // (live, at 50 lines/s, the oldest line — the selected one — can leave the list first)
            ui.fxRun(() -> ui.robot.lookup("#debug-lines").queryAs(ListView.class).getSelectionModel().select(0));
            ui.fxRun(() -> ui.robot.lookup("#debug-copy").queryButton().fire());
            ui.await(10, () -> ui.robot.lookup("#debug-feedback").queryLabeled().getText().equals("copied 1 line (selected)"));
            assertTrue(ui.fx(() -> javafx.scene.input.Clipboard.getSystemClipboard().getString()).contains("ball at"));
            ui.fxRun(() -> ui.robot.lookup("#debug-pause").queryAs(javafx.scene.control.ToggleButton.class).setSelected(false));
            ui.await(10, () -> ui.robot.lookup("#debug-count").queryLabeled().getText().endsWith(" lines"));
        }
    }

    private long counted(String prefix) throws Exception {
        String text = ui.fx(() -> ui.robot.lookup("#debug-count").queryLabeled().getText());
        return text.startsWith(prefix) && !text.isEmpty()
                ? Long.parseLong(text.substring(prefix.length()).replace(" new", "").replace(" lines", "")) : -1;
    }

    /** The network console alone, robot {@code robotId} (started) sending its demo text: the console's table. */
    @SuppressWarnings("unchecked")
    private TableView<Envelope> networkTableWithText(int robotId) throws Exception {
        only("network");
        ui.await(15, () -> ui.console.field().options().options(robotId).listReceived());
        ui.console.optionSwitches().set(robotId, "demo.text", true);
        return ui.fx(() -> ui.robot.lookup("#network-table").queryAs(TableView.class));
    }

    /**
     * Down in the network console's table while it follows selects the newest row, in view; the table's
     * own key selected the oldest of the 200 or more rows it held, out of view.
     */
    @Test
    void downInAFollowingNetworkConsoleSelectsTheNewestRow() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(6, ui.port(), "--rate", "50").start()) {
            TableView<Envelope> table = networkTableWithText(6);
            ui.await(20, () -> ui.fx(() -> table.getItems().size()) >= 250); // more than a tail of 200
            ui.fxRun(() -> ui.window.scene().getWindow().requestFocus());
            ui.fxRun(table::requestFocus);
            ui.await(10, () -> ui.window.scene().getFocusOwner() == table);
            Envelope newestBefore = ui.fx(() -> table.getItems().get(table.getItems().size() - 1));
            ui.robot.type(KeyCode.DOWN);
            ui.await(10, () -> ui.fx(() -> table.getSelectionModel().getSelectedIndex()) >= 0);
            // rows keep coming (about 50 a second): the one selected is the newest at the key or a later one,
            // never one held before it (the oldest held was 200 or more rows back)
            int[] at = ui.fx(() -> {
                List<Envelope> rows = table.getItems();
                int before = rows.size() - 1;
                while (before >= 0 && rows.get(before) != newestBefore) {
                    before--;
                }
                return new int[] {table.getSelectionModel().getSelectedIndex(), before, rows.size()};
            });
            assertTrue(at[1] >= 0, "the newest row before the key is still held");
            assertTrue(at[0] >= at[1], "the newest row selected, not an older one: row " + at[0] + ", newest before the key "
                    + at[1] + ", of " + at[2]);
        }
    }

    @Test
    @SuppressWarnings("unchecked")
    void theNetworkConsoleKeepsTheSelectedRowInViewAndShowsAscii() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(5, ui.port(), "--rate", "1000").start()) {
            TableView<Envelope> table = networkTableWithText(5);
            ui.await(20, () -> shownRows() >= 1_900);
            // following, the table holds only the newest 200 to 400 rows (LogList); a click holds them all
            assertTrue(ui.fx(() -> table.getItems().size()) <= 400, "following: only the newest rows in the table");
            Envelope chosen = ui.fx(() -> {
                int i = table.getItems().size() - 20;
                table.getSelectionModel().select(i);
                table.scrollTo(i - 3);
                return table.getItems().get(i);
            });
            ui.await(10, () -> ui.fx(() -> table.getItems().size()) >= 1_900);
            assertSame(chosen, ui.fx(() -> table.getSelectionModel().getSelectedItem()), "the clicked row stays selected");
            ui.await(10, () -> visible(table, chosen));
            Envelope oldest = ui.fx(() -> table.getItems().get(0));
            // a few hundred of the oldest rows go while the user looks at the chosen one
            ui.await(20, () -> table.getItems().indexOf(oldest) < 0 && table.getItems().indexOf(chosen) < 1_500);
            ui.await(10, () -> visible(table, chosen));
            assertSame(chosen, ui.fx(() -> table.getSelectionModel().getSelectedItem()));

            String hex = ui.fx(() -> ((TextArea) ui.robot.lookup("#network-hex").query()).getText());
            assertTrue(hex.lines().skip(1).findFirst().orElseThrow().matches("0000  ([0-9a-f]{2} ){8} ([0-9a-f]{2} |   ){8} \\|.*\\|"),
                    hex);
        }
    }

    /** The rows the network console holds, from its count ("N shown of M kept"). */
    private long shownRows() throws Exception {
        String text = ui.fx(() -> ui.robot.lookup("#network-count").queryLabeled().getText());
        return text.contains(" shown of ") ? Long.parseLong(text.substring(0, text.indexOf(' '))) : -1;
    }

    /** The item is on one of the table's rows on screen. */
    private static boolean visible(TableView<Envelope> table, Envelope e) {
        var flow = (javafx.scene.control.skin.VirtualFlow<?>) table.lookup(".virtual-flow");
        int i = table.getItems().indexOf(e);
        return flow != null && flow.getFirstVisibleCell() != null && i >= flow.getFirstVisibleCell().getIndex()
                && i <= flow.getLastVisibleCell().getIndex();
    }
}
