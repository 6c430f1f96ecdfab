package touchline.ui.render;

import javafx.beans.property.ReadOnlyStringWrapper;
import javafx.beans.value.ObservableValue;
import javafx.collections.ObservableList;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * A table's rows brought up to date cell by cell: each row holds the texts its cells show, one
 * observable text per column, and an update changes only the texts that changed, so JavaFX
 * redraws those cells and nothing else. The table's list of rows changes only when rows come or
 * go. Any change to that list (even one row replaced) makes JavaFX's table re-style and lay out
 * every cell it has, empty rows included: for the Robots table with three robots, 340 cells twice
 * a second, two thirds of all the garbage the window made (docs/archive/benchmarks-sessions.md, "Fifteenth
 * session"). The rows keep the order they have in the table (the user's sort).
 *
 * @param <T> what a row shows
 */
public final class LiveRows<T> {

    /** One row: the newest value it shows and the text of each of its cells. */
    public static final class Row<T> {
        private final Object key;
        private T value;
        private final List<ReadOnlyStringWrapper> texts = new ArrayList<>();

        private Row(Object key, T value, List<String> texts) {
            this.key = key;
            this.value = value;
            for (String t : texts) {
                this.texts.add(new ReadOnlyStringWrapper(t));
            }
        }

        /** The newest value this row shows. */
        public T value() {
            return value;
        }

        /** The text of column {@code column}, as its cell shows it. */
        public ObservableValue<String> text(int column) {
            return texts.get(column).getReadOnlyProperty();
        }

        /** Takes the texts of {@code fresh}; returns how many changed. */
        private int show(T fresh, List<String> now) {
            value = fresh;
            int changed = 0;
            for (int i = 0; i < now.size(); i++) {
                if (!now.get(i).equals(texts.get(i).get())) {
                    texts.get(i).set(now.get(i));
                    changed++;
                }
            }
            return changed;
        }
    }

    private final Function<T, Object> key;
    private final Function<T, List<String>> texts;

    /**
     * @param key   what makes a row the same row from one update to the next
     * @param texts the texts the row shows, one per column, in column order
     */
    public LiveRows(Function<T, Object> key, Function<T, List<String>> texts) {
        this.key = key;
        this.texts = texts;
    }

    /**
     * Brings {@code items} up to {@code fresh}: the same rows get their changed texts; when rows
     * came or went the list is set afresh. Returns how many cells changed (every cell of every
     * row when the list was set afresh).
     */
    public int update(ObservableList<Row<T>> items, List<T> fresh) {
        Map<Object, T> byKey = new HashMap<>();
        for (T t : fresh) {
            byKey.put(key.apply(t), t);
        }
        boolean sameRows = byKey.size() == fresh.size() && items.size() == fresh.size();
        for (int i = 0; sameRows && i < items.size(); i++) {
            sameRows = byKey.containsKey(items.get(i).key);
        }
        if (!sameRows) {
            List<Row<T>> rows = new ArrayList<>();
            int cells = 0;
            for (T t : fresh) {
                List<String> now = texts.apply(t);
                rows.add(new Row<>(key.apply(t), t, now));
                cells += now.size();
            }
            items.setAll(rows);
            return cells;
        }
        int changed = 0;
        for (Row<T> row : items) {
            T now = byKey.get(row.key);
            changed += row.show(now, texts.apply(now));
        }
        return changed;
    }
}
