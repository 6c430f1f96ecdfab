package touchline.ui;

import java.util.Set;
import java.util.function.BiFunction;

/**
 * One registry entry: everything the shell needs to offer a view — its menu and quick-open
 * title, the help text, which option kinds (DebugKind numbers) it visualises, and how to make
 * one.
 *
 * @param id      stable name used in layout files
 * @param kinds   DebugKind numbers this view opens for on double-click; empty for the fixed views
 */
public record ViewSpec(String id, String title, String help, Set<Integer> kinds,
                       BiFunction<ViewContext, ViewSource, View> factory) {

    public boolean visualisation() {
        return !kinds.isEmpty();
    }
}
