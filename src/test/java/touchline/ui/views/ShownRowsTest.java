package touchline.ui.views;

import javafx.collections.FXCollections;
import javafx.collections.ListChangeListener;
import javafx.collections.ObservableList;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ShownRowsTest {

    record Row(int id, String rate, long packets) { }

    /** Shows id and rate, not the packet count. */
    private final ShownRows<Row> rows = new ShownRows<>(Row::id, r -> List.of(Integer.toString(r.id()), r.rate()));
    private final ObservableList<Row> items = FXCollections.observableArrayList();
    private final List<String> changes = new ArrayList<>();

    ShownRowsTest() {
        items.addListener((ListChangeListener<Row>) c -> {
            while (c.next()) {
                changes.add(c.wasReplaced() ? "replaced " + c.getFrom() + ".." + c.getTo()
                        : c.wasAdded() ? "added " + c.getAddedSize() : "removed " + c.getRemovedSize());
            }
        });
    }

    @Test
    void aRowIsReplacedOnlyWhenAShownTextChanged() {
        rows.update(items, List.of(new Row(1, "5.0", 10), new Row(2, "7.0", 20)));
        changes.clear();

        Row unchanged = items.get(0);
        assertEquals(1, rows.update(items, List.of(new Row(1, "5.0", 11), new Row(2, "8.0", 21))));
        assertEquals(List.of("replaced 1..2"), changes);
        assertSame(unchanged, items.get(0), "a row showing the same texts stays the object it was");
        assertEquals("8.0", items.get(1).rate());

        changes.clear();
        assertEquals(0, rows.update(items, List.of(new Row(1, "5.0", 12), new Row(2, "8.0", 22))));
        assertTrue(changes.isEmpty(), "nothing shown changed: no change at all, so nothing is redrawn");
    }

    @Test
    void theTablesOrderIsKept() {
        rows.update(items, List.of(new Row(1, "5.0", 10), new Row(2, "7.0", 20)));
        FXCollections.reverse(items); // the user sorted by a column
        rows.update(items, List.of(new Row(1, "6.0", 11), new Row(2, "7.0", 21)));
        assertEquals(List.of(2, 1), items.stream().map(Row::id).toList());
        assertEquals("6.0", items.get(1).rate());
    }

    @Test
    void aRobotComingOrGoingSetsTheListAfresh() {
        rows.update(items, List.of(new Row(1, "5.0", 10)));
        changes.clear();
        assertEquals(2, rows.update(items, List.of(new Row(1, "5.0", 10), new Row(3, "1.0", 1))));
        assertEquals(List.of(1, 3), items.stream().map(Row::id).toList());
        assertEquals(1, rows.update(items, List.of(new Row(3, "1.0", 2))));
        assertEquals(List.of(3), items.stream().map(Row::id).toList());
        assertEquals(0, rows.update(items, List.of(new Row(3, "1.0", 3))), "the new row's texts were remembered");
    }
}
