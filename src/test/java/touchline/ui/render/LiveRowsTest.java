package touchline.ui.render;

import javafx.beans.InvalidationListener;
import javafx.collections.FXCollections;
import javafx.collections.ListChangeListener;
import javafx.collections.ObservableList;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LiveRowsTest {

    record Robot(int id, String rate, long packets) { }

    /** Shows id and rate, not the packet count. */
    private final LiveRows<Robot> rows = new LiveRows<>(Robot::id, r -> List.of(Integer.toString(r.id()), r.rate()));
    private final ObservableList<LiveRows.Row<Robot>> items = FXCollections.observableArrayList();
    private final List<String> listChanges = new ArrayList<>();
    private final List<String> cellChanges = new ArrayList<>();

    LiveRowsTest() {
        items.addListener((ListChangeListener<LiveRows.Row<Robot>>) c -> {
            while (c.next()) {
                listChanges.add(c.wasReplaced() ? "replaced " + c.getFrom() + ".." + c.getTo()
                        : c.wasAdded() ? "added " + c.getAddedSize() : "removed " + c.getRemovedSize());
            }
        });
    }

    /** Records every change of every cell's text, as a table cell bound to it would see it. */
    private void watchCells() {
        for (LiveRows.Row<Robot> row : items) {
            for (int column = 0; column < 2; column++) {
                String cell = row.value().id() + "/" + column;
                row.text(column).addListener((InvalidationListener) o -> cellChanges.add(cell));
            }
        }
    }

    @Test
    void onlyTheCellsWhoseTextChangedChangeAndTheListStaysAsItIs() {
        rows.update(items, List.of(new Robot(1, "5.0", 10), new Robot(2, "7.0", 20)));
        LiveRows.Row<Robot> first = items.get(0);
        listChanges.clear();
        watchCells();

        assertEquals(1, rows.update(items, List.of(new Robot(1, "5.0", 11), new Robot(2, "8.0", 21))));
        assertEquals(List.of(), listChanges, "the same robots: the table's list of rows does not change");
        assertEquals(List.of("2/1"), cellChanges, "only robot 2's rate changed");
        assertEquals("8.0", items.get(1).text(1).getValue());
        assertSame(first, items.get(0));
        assertEquals(11, items.get(0).value().packets(), "each row holds the newest value, shown or not");

        cellChanges.clear();
        assertEquals(0, rows.update(items, List.of(new Robot(1, "5.0", 12), new Robot(2, "8.0", 22))));
        assertTrue(cellChanges.isEmpty(), "nothing shown changed: no cell changes, so nothing is redrawn");
    }

    @Test
    void theTablesOrderIsKept() {
        rows.update(items, List.of(new Robot(1, "5.0", 10), new Robot(2, "7.0", 20)));
        FXCollections.reverse(items); // the user sorted by a column
        rows.update(items, List.of(new Robot(1, "6.0", 11), new Robot(2, "7.0", 21)));
        assertEquals(List.of(2, 1), items.stream().map(r -> r.value().id()).toList());
        assertEquals("6.0", items.get(1).text(1).getValue());
    }

    @Test
    void aRobotComingOrGoingSetsTheListAfresh() {
        rows.update(items, List.of(new Robot(1, "5.0", 10)));
        listChanges.clear();
        assertEquals(4, rows.update(items, List.of(new Robot(1, "5.0", 10), new Robot(3, "1.0", 1))));
        assertEquals(List.of(1, 3), items.stream().map(r -> r.value().id()).toList());
        assertEquals(List.of("replaced 0..2"), listChanges);
        assertEquals(2, rows.update(items, List.of(new Robot(3, "1.0", 2))));
        assertEquals(List.of(3), items.stream().map(r -> r.value().id()).toList());
        assertEquals(0, rows.update(items, List.of(new Robot(3, "1.0", 3))), "the new row's texts were taken");
    }
}
