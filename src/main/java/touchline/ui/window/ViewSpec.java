package touchline.ui.window;

import java.util.Set;
import java.util.function.BiFunction;
import touchline.ui.frame.View;
import touchline.ui.frame.ViewSource;

/**
 * One registry entry: everything the shell needs to offer a view — its menu and quick-open
 * title, the help text, which option kinds (DebugKind numbers) it visualises, and how to make
 * one.
 *
 * @param id        stable name used in layout files
 * @param kinds     DebugKind numbers this view opens for on double-click; empty for the fixed views
 * @param needWidth the width in pixels its controls need side by side (0: any pane will do); a view
 *                  opened into a layout with no pane that wide gets a row of the window's whole width
 */
public record ViewSpec(String id, String title, String help, Set<Integer> kinds,
                       BiFunction<ViewContext, ViewSource, View> factory, double needWidth) {

    public ViewSpec(String id, String title, String help, Set<Integer> kinds,
                    BiFunction<ViewContext, ViewSource, View> factory) {
        this(id, title, help, kinds, factory, 0);
    }

    public boolean visualisation() {
        return !kinds.isEmpty();
    }
}
