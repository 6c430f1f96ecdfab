package touchline.ui.render;

import javafx.beans.property.ReadOnlyObjectWrapper;
import javafx.beans.value.ObservableValue;
import javafx.scene.control.TableColumn;
import javafx.scene.text.Font;
import javafx.scene.text.FontWeight;
import javafx.scene.text.Text;

import java.util.function.Function;

/**
 * Text columns of a table that are never narrower than their header or their widest usual
 * value: on a 1280-pixel laptop a header reads "Battery", not "Bat…", and a time keeps its
 * milliseconds. The table scrolls sideways when the columns are wider than the view.
 */
public final class TextColumns<T> {

    /** Cell and header padding plus room for a sort arrow, in pixels. */
    private static final double PADDING = 28;
    /** The theme's text size (AtlantaFX Primer). */
    private static final double FONT_SIZE = 14;

    private final Font header = Font.font(Font.getDefault().getFamily(), FontWeight.BOLD, FONT_SIZE);
    private final Font cell = Font.font(Font.getDefault().getFamily(), FONT_SIZE);
    private final boolean sortable;

    public TextColumns(boolean sortable) {
        this.sortable = sortable;
    }

    /** A column at least {@code width} wide, and wide enough for its title and for {@code widest}. */
    public TableColumn<T, String> column(String title, Function<T, String> value, double width, String widest) {
        return observed(title, row -> new ReadOnlyObjectWrapper<>(value.apply(row)), width, widest);
    }

    /** The same, for a text the row keeps up to date itself: a change redraws that one cell ({@link LiveRows}). */
    public TableColumn<T, String> observed(String title, Function<T, ObservableValue<String>> value, double width, String widest) {
        TableColumn<T, String> c = new TableColumn<>(title);
        c.setCellValueFactory(cell -> value.apply(cell.getValue()));
        double fit = Math.ceil(Math.max(width(title, header), width(widest, cell)) + PADDING);
        c.setMinWidth(fit);
        c.setPrefWidth(Math.max(width, fit));
        c.setSortable(sortable);
        return c;
    }

    private static double width(String s, Font font) {
        if (s == null || s.isEmpty()) {
            return 0;
        }
        Text t = new Text(s);
        t.setFont(font);
        return t.getLayoutBounds().getWidth();
    }
}
