package touchline.ui.consoles;

import javafx.beans.property.ReadOnlyStringWrapper;
import javafx.collections.FXCollections;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableView;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/** A robot's debug table as sent: its header and rows; short rows are padded, not rejected. */
public final class TableDataView extends SourcedView {

    private final TableView<List<String>> table = new TableView<>();
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
            table.getColumns().clear();
            for (int i = 0; i < width; i++) {
                final int col = i;
                TableColumn<List<String>, String> c = new TableColumn<>(h.get(i));
                c.setCellValueFactory(cell -> new ReadOnlyStringWrapper(
                        col < cell.getValue().size() ? cell.getValue().get(col) : ""));
                table.getColumns().add(c);
            }
        }
        List<List<String>> rows = new ArrayList<>();
        for (Fumanoid.TableRow r : t.getRowsList()) {
            rows.add(r.getCellsList());
        }
        table.setItems(FXCollections.observableArrayList(rows));
        return rows.size() + " rows × " + width + " columns";
    }
}
