package touchline.ui.render;

import javafx.scene.Node;
import javafx.scene.control.ScrollBar;
import javafx.scene.control.TableView;
import javafx.geometry.Orientation;

/**
 * A table as tall as its rows (and its header and sideways scroll bar), at least
 * {@code minRows} tall so its placeholder fits; in a box that is shorter it scrolls as any
 * table does. JavaFX's table otherwise fills its whole height with empty rows, one cell per
 * column each, which every changed frame walks and styles again (docs/archive/benchmarks-sessions.md,
 * "Sixteenth session"). Rows have one fixed height.
 */
public final class FittedTable<T> extends TableView<T> {

    private final int minRows;
    /** The sideways bar's height the last preferred height counted: a bar that came or went since asks for a new one. */
    private double barCounted;
    private final SkinPart<Node> header = new SkinPart<>(this, ".column-header-background", Node.class);
    private final SkinPart<ScrollBar> sideways = new SkinPart<>(this, ".scroll-bar", ScrollBar.class,
            b -> b.getOrientation() == Orientation.HORIZONTAL);

    public FittedTable(double rowHeight, int minRows) {
        this.minRows = minRows;
        setFixedCellSize(rowHeight);
        setMaxHeight(USE_PREF_SIZE); // the table's skin lays it out again when its rows change
    }

    @Override
    protected double computePrefHeight(double width) {
        double rows = Math.max(minRows, getItems().size()) * getFixedCellSize();
        barCounted = sidewaysBarHeight();
        return snappedTopInset() + shownHeight(header.get()) + rows
                + barCounted + snappedBottomInset();
    }

    @Override
    protected void layoutChildren() {
        super.layoutChildren();
        if (sidewaysBarHeight() != barCounted) {
            requestLayout(); // the columns outgrew the table, or fit it again
        }
    }

    /** The sideways scroll bar's height while it shows (columns wider than the table), else 0. */
    private double sidewaysBarHeight() {
        return shownHeight(sideways.get());
    }

    private static double shownHeight(Node n) {
        return n == null || !n.isVisible() ? 0 : n.prefHeight(-1);
    }
}
