package touchline.ui.consoles;

import javafx.scene.Scene;
import javafx.scene.control.ListCell;
import javafx.scene.control.ListView;
import javafx.scene.control.skin.VirtualFlow;
import javafx.scene.layout.StackPane;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.model.store.SequencedRing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

class LogListTest {

    /** Rows on screen: a 220-px list of 22-px rows. */
    private static final int ROWS = 10;

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    private final SequencedRing<String> ring = new SequencedRing<>(5_000);
    /** Times a row was given another line to show. */
    private int newTexts;

    private ListView<String> list() {
        ListView<String> list = new ListView<>();
        list.setFixedCellSize(22);
        list.setCellFactory(l -> new ListCell<>() {
            @Override
            protected void updateItem(String item, boolean empty) {
                String was = getText();
                super.updateItem(item, empty);
                setText(empty ? null : item);
                if (!empty && !item.equals(was)) {
                    newTexts++;
                }
            }
        });
        new Scene(new StackPane(list), 300, ROWS * 22 + 2);
        return list;
    }

    /** One frame: the log follows the ring, the list is laid out as a pulse would. */
    private void frame(LogList<String, String> log, ListView<String> list) {
        log.follow(true, ring.version(), ring::since, s -> s);
        list.getParent().applyCss();
        list.getParent().layout();
    }

    private static String lastOnScreen(ListView<String> list) {
        VirtualFlow<?> flow = (VirtualFlow<?>) list.lookup(".virtual-flow");
        javafx.scene.control.IndexedCell<?> last = flow.getLastVisibleCell();
        return last == null ? null : ((ListCell<?>) last).getText();
    }

    @Test
    void followingALongLogDrawsOnlyTheNewLinesAndCutsTheOldestInOneGo() throws Exception {
        fx(() -> {
            ListView<String> list = list();
            LogList<String, String> log = new LogList<>(list, 5_000);
            for (int i = 1; i <= LogList.TAIL; i++) {
                ring.append("line " + i);
                frame(log, list);
                assertEquals("line " + i, lastOnScreen(list), "the newest line on screen, last");
            }
            int frames = 3 * LogList.TRIM_SLACK; // a line a frame, the tail full all along
            int cuts = 0;
            newTexts = 0;
            for (int i = LogList.TAIL + 1; i <= LogList.TAIL + frames; i++) {
                int before = list.getItems().size();
                ring.append("line " + i);
                frame(log, list);
                if (list.getItems().size() < before) {
                    cuts++;
                }
                assertEquals("line " + i, lastOnScreen(list), "the newest line on screen, last");
                assertTrue(list.getItems().size() >= LogList.TAIL && list.getItems().size() <= LogList.TAIL + LogList.TRIM_SLACK,
                        "the tail holds " + LogList.TAIL + " to " + (LogList.TAIL + LogList.TRIM_SLACK) + " lines: "
                                + list.getItems().size());
            }
            assertEquals(frames / (LogList.TRIM_SLACK + 1), cuts, "the oldest lines go in a cut every " + LogList.TRIM_SLACK + " lines");
            // scrolling with the list's scrollTo, or cutting a line a frame, gave every row on screen
            // another line in every frame (ROWS × frames); a cut still does, a few times over
            assertTrue(newTexts <= frames + (cuts + 1) * 3 * ROWS,
                    newTexts + " lines drawn in " + frames + " frames: only the new line, and the rows on screen at a cut");
            return null;
        });
    }

    /**
     * Issue 36 item 4: a row chosen with the keyboard (Up into a table that follows, as the network
     * console's) stays the selected, focused row while lines arrive and the oldest go in cuts; when
     * the chosen line itself goes with the oldest, the selection is cleared (the log follows again)
     * rather than sliding onto the oldest line left, another datagram at every cut (it changed
     * under the user every second or two at the demo's rates).
     */
    @Test
    void aChosenRowStaysSelectedThroughTheCutsAndNeverSlidesOntoAnother() throws Exception {
        fx(() -> {
            javafx.scene.control.TableView<String> table = new javafx.scene.control.TableView<>();
            javafx.scene.control.TableColumn<String, String> c = new javafx.scene.control.TableColumn<>("line");
            c.setCellValueFactory(d -> new javafx.beans.property.SimpleStringProperty(d.getValue()));
            table.getColumns().add(c);
            new Scene(new StackPane(table), 300, 300);
            LogList<String, String> log = new LogList<>(table, 1_000);
            int n = 0;
            for (; n < 900; n++) {
                ring.append("line " + n);
            }
            log.follow(true, ring.version(), ring::since, s -> s);
            table.getParent().applyCss();
            table.getParent().layout();
            table.requestFocus();
            javafx.event.Event.fireEvent(table, new javafx.scene.input.KeyEvent(javafx.scene.input.KeyEvent.KEY_PRESSED,
                    "", "", javafx.scene.input.KeyCode.UP, false, false, false, false));
            String chosen = table.getSelectionModel().getSelectedItem();
            assertEquals("line 899", chosen);
            int cutsWhileHeld = 0;
            int frame = 0;
            for (; frame < 400 && !table.getSelectionModel().isEmpty(); frame++) { // 10 lines a frame
                for (int k = 0; k < 10; k++) {
                    ring.append("line " + n++);
                }
                int before = log.all().size();
                log.follow(false, ring.version(), ring::since, s -> s);
                table.getParent().applyCss();
                table.getParent().layout();
                String selected = table.getSelectionModel().getSelectedItem();
                if (selected != null) {
                    assertEquals(chosen, selected, "frame " + frame);
                    assertEquals(chosen, table.getItems().get(table.getFocusModel().getFocusedIndex()), "focus, frame " + frame);
                    if (log.all().size() < before + 10) {
                        cutsWhileHeld++;
                    }
                }
            }
            assertTrue(cutsWhileHeld >= 3, cutsWhileHeld + " cuts of the oldest while the chosen line stayed");
            assertTrue(table.getSelectionModel().isEmpty() && !log.all().contains(chosen),
                    "the chosen line went with the oldest after " + frame + " frames: nothing selected");
            return null;
        });
    }
}
