package touchline.ui.consoles;

import javafx.scene.control.ComboBox;
import javafx.scene.control.IndexedCell;
import javafx.scene.control.ListView;
import javafx.scene.control.TableView;
import javafx.scene.control.ToggleButton;
import javafx.scene.control.skin.VirtualFlow;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import touchline.testing.RobotProcess;
import touchline.testing.UiTest;
import touchline.transport.Envelope;
import touchline.ui.window.LayoutNode;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.window.ConsoleWindowFixture;

/**
 * Issue 36 items 2 and 4, in the real window (headless) with a robot sending: the robot filter of
 * the Debug console, the Network console and Plot fields offers the robot that reports (its first
 * read was never due: a "never read" time of Long.MIN_VALUE overflowed the twice-a-second check);
 * a line the user selects in the Network console stays selected and shown while rows keep coming
 * and the oldest go, and the console says it holds it; Pause in the Debug console freezes the
 * lines that were on screen.
 */
@UiTest
@Tag("integration")
class LogViewsUiTest {

    private ConsoleWindowFixture ui;

    private void only(String viewId, String control) throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry(viewId, ""))))));
        ui.await(30, () -> ui.robot.lookup(control).tryQuery().map(n -> n.getScene() != null).orElse(false));
    }

    /** View {@code viewId} alone, once its {@code control} is in the scene, and the robot's demo text switched on. */
    private void onlyWithText(String viewId, String control, int robotId) throws Exception {
        only(viewId, control);
        ui.await(15, () -> ui.console.field().options().options(robotId).listReceived());
        ui.console.optionSwitches().set(robotId, "demo.text", true);
    }

    @ParameterizedTest
    @CsvSource({"debug-console, #debug-robot", "network, #network-robot", "field-plot, #field-robot"})
    @SuppressWarnings("unchecked")
    void theRobotFilterOffersTheRobotThatReports(String viewId, String filterId) throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(7, ui.port(), "--rate", "20").start()) {
            only(viewId, filterId);
            ui.await(30, () -> ui.console.field().robots().robots().stream().anyMatch(r -> r.id() == 7));
            ui.await(30, () -> ui.robot.lookup(filterId).queryAs(ComboBox.class).getItems().contains("robot 7"));
            ComboBox<String> filter = ui.fx(() -> ui.robot.lookup(filterId).queryAs(ComboBox.class));
            ui.fxRun(() -> filter.getSelectionModel().select("robot 7"));
            ui.await(30, () -> "robot 7".equals(filter.getValue())); // chosen and kept over the next refreshes
        }
    }

    /** The indices of the first and last row on screen. */
    private static int[] onScreen(javafx.scene.control.Control control) {
        VirtualFlow<?> flow = (VirtualFlow<?>) control.lookup(".virtual-flow");
        IndexedCell<?> first = flow.getFirstVisibleCell();
        IndexedCell<?> last = flow.getLastVisibleCell();
        return first == null || last == null ? null : new int[] {first.getIndex(), last.getIndex()};
    }

    @Test
    @SuppressWarnings("unchecked")
    void aClickedDatagramStaysSelectedAndShownWhileTheOldestGo() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(5, ui.port(), "--rate", "400").start()) {
            onlyWithText("network", "#network-table", 5);
            TableView<Envelope> table = ui.fx(() -> ui.robot.lookup("#network-table").queryAs(TableView.class));
            ui.await(30, () -> table.getItems().size() >= 150);
            // a user's click on a row in the middle of the screen
            IndexedCell<?> cell = ui.fx(() -> {
                int[] shown = onScreen(table);
                int middle = (shown[0] + shown[1]) / 2;
                return (IndexedCell<?>) table.lookupAll(".table-row-cell").stream()
                        .filter(n -> ((IndexedCell<?>) n).getIndex() == middle).findFirst().orElseThrow();
            });
            ui.robot.clickOn(cell);
            ui.await(30, () -> table.getSelectionModel().getSelectedItem() != null);
            Envelope chosen = ui.fx(() -> table.getSelectionModel().getSelectedItem());
            String detail = ui.fx(() -> ((javafx.scene.control.TextArea) ui.robot.lookup("#network-hex").query()).getText());
            // rows keep coming until the oldest go (2 000 held, a tenth more before they go)
            ui.await(60, () -> table.getItems().size() > 2_000 || table.getItems().indexOf(chosen) < 0);
            Envelope oldest = ui.fx(() -> table.getItems().get(0));
            ui.await(60, () -> table.getItems().indexOf(oldest) < 0);
            assertSame(chosen, ui.fx(() -> table.getSelectionModel().getSelectedItem()), "the clicked datagram stays selected");
            ui.await(30, () -> ui.robot.lookup("#network-count").queryLabeled().getText()
                    .endsWith(" · held at the selected row (Ctrl+click it to follow)")); // and the console says it stopped following
            assertEquals(detail, ui.fx(() -> ((javafx.scene.control.TextArea) ui.robot.lookup("#network-hex").query()).getText()));
        }
    }

    @Test
    @SuppressWarnings("unchecked")
    void pauseInTheDebugConsoleFreezesTheLinesOnScreen() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(4, ui.port(), "--rate", "50").start()) {
            onlyWithText("debug-console", "#debug-lines", 4);
            ListView<String> lines = ui.fx(() -> ui.robot.lookup("#debug-lines").queryAs(ListView.class));
            ui.await(30, () -> {
                String count = ui.robot.lookup("#debug-count").queryLabeled().getText();
                return count.endsWith(" lines") && Integer.parseInt(count.substring(0, count.indexOf(' '))) >= 300;
            });
            ui.fxRun(() -> ui.robot.lookup("#debug-pause").queryAs(ToggleButton.class).setSelected(true));
            ui.await(30, () -> ui.robot.lookup("#debug-count").queryLabeled().getText().startsWith("paused"));
            int[] shown = ui.fx(() -> onScreen(lines));
            int held = ui.fx(() -> lines.getItems().size());
            assertEquals(held - 1, shown[1], "the newest line stays at the bottom: rows " + shown[0] + "–" + shown[1] + " of " + held);
            assertTrue(shown[1] - shown[0] < 100);
        }
    }
}
