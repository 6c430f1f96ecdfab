package touchline.ui.consoles;

import javafx.scene.control.TableColumn;
import javafx.scene.control.TableView;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.frame.SourcedView;
import touchline.ui.render.LiveRows;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * A robot's debug table as sent: its header and rows; short rows are padded, not rejected. A
 * table that comes again with the same number of rows keeps its rows and changes only the cells
 * whose text changed ({@link LiveRows}): a ROS 2 robot's 24 joints at 30 Hz set afresh re-styled
 * and laid out every cell each frame (docs/archive/benchmarks-sessions.md, "Window CPU with eight
 * bridges").
 */
public final class TableDataView extends SourcedView {

    /** Row {@code index} of the table, its cells padded to the table's width. */
    private record Line(int index, List<String> cells) { }

    private final TableView<LiveRows.Row<Line>> table = new TableView<>();
    private final LiveRows<Line> rows = new LiveRows<>(Line::index, Line::cells);
    private List<String> header = List.of();

    public TableDataView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.TABLE_VALUE), source);
        table.setId("data-table");
        root.setCenter(table);
    }

    @Override
    protected String draw(Latest latest) {
        if (!(latest.data() instanceof Fumanoid.DebugTable t)) {
            return "not a table: " + latest.kind();
        }
        int width = t.getHeaderCount();
        for (Fumanoid.TableRow r : t.getRowsList()) {
            width = Math.max(width, r.getCellsCount());
        }
        List<String> h = new ArrayList<>();
        for (int i = 0; i < width; i++) {
            h.add(i < t.getHeaderCount() ? t.getHeader(i) : "column " + (i + 1));
        }
        if (!h.equals(header)) {
            header = h;
            table.getItems().clear(); // the rows' cells are as many as the columns
            table.getColumns().clear();
            for (int i = 0; i < width; i++) {
                final int col = i;
                TableColumn<LiveRows.Row<Line>, String> c = new TableColumn<>(h.get(i));
                c.setCellValueFactory(cell -> cell.getValue().text(col));
                table.getColumns().add(c);
            }
        }
        List<Line> lines = new ArrayList<>();
        for (Fumanoid.TableRow r : t.getRowsList()) {
            List<String> cells = new ArrayList<>(r.getCellsList());
            while (cells.size() < width) {
                cells.add("");
            }
            lines.add(new Line(lines.size(), cells));
        }
        rows.update(table.getItems(), lines);
        return lines.size() + " rows × " + width + " columns";
    }
}
