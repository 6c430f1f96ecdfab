package touchline.ui.render;

import javafx.scene.Scene;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableRow;
import javafx.scene.control.TableView;
import javafx.scene.layout.VBox;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

class FittedTableTest {

    private static final double ROW = 40;

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    /** A table of {@code columns} text columns, 100 px each, in a 400 × 600 box laid out at once. */
    private static TableView<String> table(int columns) {
        FittedTable<String> table = new FittedTable<>(ROW, 3);
        for (int i = 0; i < columns; i++) {
            TableColumn<String, String> c = new TableColumn<>("c" + i);
            c.setCellValueFactory(d -> new javafx.beans.property.ReadOnlyStringWrapper(d.getValue()));
            c.setPrefWidth(100);
            table.getColumns().add(c);
        }
        new Scene(new VBox(table), 400, 600);
        layOut(table);
        return table;
    }

    private static void layOut(TableView<String> table) {
        for (int i = 0; i < 3; i++) { // a bar that came with the layout asks for one more
            table.getParent().applyCss();
            table.getParent().layout();
        }
    }

    private static long rowCells(TableView<String> table) {
        return table.lookupAll(".table-row-cell").stream().filter(n -> n.isVisible() && n instanceof TableRow<?>).count();
    }

    @Test
    void aTableIsAsTallAsItsRowsAndHoldsNoEmptyOnes() throws Exception {
        TableView<String> table = fx(() -> table(2));
        double empty = fx(() -> table.getHeight());
        fx(() -> {
            table.getItems().addAll("a", "b", "c", "d", "e");
            layOut(table);
            return null;
        });
        assertEquals(empty + 2 * ROW, fx(table::getHeight), 0.5, "five rows: two more than the three an empty table keeps room for");
        assertEquals(5, fx(() -> rowCells(table)), "only the rows there are, no empty ones below them");
        assertTrue(fx(table::getHeight) < 600, "shorter than its box");
        fx(() -> {
            table.getItems().remove(0, 4);
            layOut(table);
            return null;
        });
        assertEquals(empty, fx(table::getHeight), 0.5, "one row: as tall as an empty table");
    }

    @Test
    void aTableWiderThanItsBoxMakesRoomForItsSidewaysBar() throws Exception {
        double narrow = fx(() -> {
            TableView<String> t = table(2);
            t.getItems().addAll("a", "b", "c", "d");
            layOut(t);
            return t.getHeight();
        });
        TableView<String> wide = fx(() -> {
            TableView<String> t = table(8); // 800 px of columns in 400
            t.getItems().addAll("a", "b", "c", "d");
            layOut(t);
            return t;
        });
        assertTrue(fx(wide::getHeight) > narrow + 5, "the sideways bar adds its height: " + narrow + " → " + fx(wide::getHeight));
        assertEquals(4, fx(() -> rowCells(wide)), "every row shows above the bar");
    }

    @Test
    void aTableLongerThanItsBoxScrolls() throws Exception {
        TableView<String> table = fx(() -> table(2));
        fx(() -> {
            for (int i = 0; i < 40; i++) {
                table.getItems().add("row " + i);
            }
            layOut(table);
            return null;
        });
        assertEquals(600, fx(table::getHeight), 0.5, "40 rows of 40 px: the box's height, and the table scrolls");
    }
}
