package touchline.ui.consoles;

import javafx.geometry.VPos;
import javafx.scene.Group;
import javafx.scene.layout.Region;
import javafx.scene.shape.Rectangle;
import javafx.scene.text.Text;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The newest lines of a log as plain text, bottom up, in rows of a fixed height: what a list that
 * follows its log shows, at a fraction of the cost (docs/archive/benchmarks-sessions.md, "Nineteenth session"). A
 * new line takes the row of the line that left the top, and the rows move up together in one step,
 * so each line is laid out once; nothing here asks the window for a layout. It cannot be selected,
 * scrolled or focused: the debug console shows it while nobody uses its list ({@link LogList#glance}).
 */
final class NewestLines extends Region implements LogList.Glance<String> {

    /** Lines kept to fill a taller pane: more rows than any screen shows (as {@link LogList#TAIL}). */
    static final int KEPT = LogList.TAIL;

    private final double rowHeight;
    private final double indent;
    private final java.util.function.DoubleSupplier barThickness;
    private final Group rows = new Group();
    private final Rectangle clip = new Rectangle();
    /** The lines shown, oldest first (up to {@link #KEPT}). */
    private final ArrayDeque<String> lines = new ArrayDeque<>();
    /** The text nodes, top row first. */
    private final ArrayDeque<Text> texts = new ArrayDeque<>();
    /** Rows counted before a full redraw numbers them afresh (a day and more at 30 lines a second). */
    static final long RENUMBER = 4_000_000;
    /** The row the next line takes, counted from the last full redraw. */
    private long next;

    /**
     * @param rowHeight    the list's row height
     * @param indent       where a row's text starts, as in the list's rows
     * @param barThickness the list's scroll bars' thickness (0 while not known): the strips the list
     *                     keeps for them, so a line stays in its place when the list comes up
     */
    NewestLines(double rowHeight, double indent, java.util.function.DoubleSupplier barThickness) {
        this.rowHeight = rowHeight;
        this.indent = indent;
        this.barThickness = barThickness;
        getStyleClass().addAll("list-view", "newest-lines"); // the list's border and colours
        rows.setManaged(false); // the rows move themselves: no layout of the window for a new line
        getChildren().add(rows);
        setClip(clip);
    }

    @Override
    public void restart(List<String> newest) {
        lines.clear();
        for (String l : newest.subList(Math.max(0, newest.size() - KEPT), newest.size())) {
            lines.addLast(l);
        }
        redraw();
    }

    @Override
    public void append(List<String> added) {
        if (added.size() >= texts.size() || next > RENUMBER) {
            restart(concat(added));
            return;
        }
        for (String l : added) {
            keep(l);
            Text t = texts.pollFirst(); // the top row's line has left the view
            t.setText(l);
            t.setLayoutY(rowY(next++));
            texts.addLast(t);
        }
        place();
    }

    private List<String> concat(List<String> added) {
        List<String> all = new ArrayList<>(lines);
        all.addAll(added);
        return all;
    }

    private void keep(String line) {
        lines.addLast(line);
        if (lines.size() > KEPT) {
            lines.pollFirst();
        }
    }

    @Override
    protected void layoutChildren() {
        if (texts.size() != rowsFor(getHeight())) {
            redraw();
        } else {
            place();
        }
    }

    /** Rows a pane of this height shows: every full row and the part-row at the top. */
    private int rowsFor(double height) {
        return Math.max(1, (int) Math.ceil(height / rowHeight) + 1);
    }

    /** Every row afresh: the newest lines bottom up, empty rows above them. */
    private void redraw() {
        int n = rowsFor(getHeight());
        while (texts.size() < n) {
            Text t = new Text();
            t.getStyleClass().add("newest-line");
            t.setTextOrigin(VPos.CENTER);
            t.setManaged(false);
            t.setLayoutX(indent);
            texts.addLast(t);
            rows.getChildren().add(t);
        }
        while (texts.size() > n) {
            rows.getChildren().remove(texts.pollFirst());
        }
        next = 0;
        List<String> shown = new ArrayList<>(lines);
        int first = shown.size() - n;
        for (Text t : texts) {
            t.setText(first >= 0 ? shown.get(first) : "");
            t.setLayoutY(rowY(next++));
            first++;
        }
        place();
    }

    /** A row's text centre, from the top of the group. */
    private double rowY(long row) {
        return row * rowHeight + rowHeight / 2;
    }

    /**
     * Moves the rows so the newest sits on the bottom edge, inside the border and above the strip
     * where the list has its horizontal scroll bar (when a line is wider than the pane), left of
     * where it has its vertical one (when there are more lines than rows).
     */
    private void place() {
        var in = getInsets();
        double bar = barThickness.getAsDouble();
        double right = lines.size() * rowHeight > getHeight() - in.getTop() - in.getBottom() ? bar : 0;
        double width = getWidth() - in.getLeft() - in.getRight() - right;
        double bottom = widest() > width ? bar : 0;
        double height = getHeight() - in.getTop() - in.getBottom() - bottom;
        clip.setX(in.getLeft());
        clip.setY(in.getTop());
        clip.setWidth(Math.max(0, width));
        clip.setHeight(Math.max(0, height));
        rows.setLayoutY(in.getTop() + height - next * rowHeight);
    }

    /** The widest line shown, from where the rows start. */
    private double widest() {
        double w = 0;
        for (Text t : texts) {
            w = Math.max(w, t.getLayoutBounds().getWidth());
        }
        return w + indent - getInsets().getLeft();
    }
}
