package touchline.ui.views;

import javafx.collections.ObservableList;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;

/**
 * Brings a table's rows up to date in place: a row is replaced only when a text it shows
 * changed, so JavaFX redraws those cells and not the whole table (in software a rebuilt table
 * cost the window a 457 × 419 pixel repaint twice a second, docs/benchmarks.md). When rows
 * came or went the list is set afresh. The rows keep the order they have in the table (the
 * user's sort).
 *
 * @param <T> a row
 */
final class ShownRows<T> {

    private final Function<T, Object> key;
    private final Function<T, List<String>> texts;
    private final Map<Object, List<String>> shown = new HashMap<>();

    /**
     * @param key   what makes a row the same row from one update to the next
     * @param texts the texts the row shows, as its cells show them now
     */
    ShownRows(Function<T, Object> key, Function<T, List<String>> texts) {
        this.key = key;
        this.texts = texts;
    }

    /** Updates {@code items} to {@code fresh}; returns how many rows changed (all of them when rows came or went). */
    int update(ObservableList<T> items, List<T> fresh) {
        Map<Object, T> byKey = new HashMap<>();
        for (T t : fresh) {
            byKey.put(key.apply(t), t);
        }
        boolean sameRows = byKey.size() == fresh.size() && items.size() == fresh.size();
        for (int i = 0; sameRows && i < items.size(); i++) {
            sameRows = byKey.containsKey(key.apply(items.get(i)));
        }
        if (!sameRows) {
            shown.clear();
            for (T t : fresh) {
                shown.put(key.apply(t), texts.apply(t));
            }
            items.setAll(fresh);
            return fresh.size();
        }
        List<Integer> changed = new ArrayList<>();
        for (int i = 0; i < items.size(); i++) {
            T now = byKey.get(key.apply(items.get(i)));
            List<String> t = texts.apply(now);
            if (!Objects.equals(shown.put(key.apply(now), t), t)) {
                changed.add(i);
            }
        }
        for (int i : changed) {
            items.set(i, byKey.get(key.apply(items.get(i))));
        }
        return changed.size();
    }
}
