package touchline.ui.window;

import java.util.List;

/**
 * A saved arrangement of views, independent of JavaFX: split panes (branches) holding tab
 * groups (leaves) holding views by registry ID and source. Plain data, so it can be written,
 * read and tested without a window.
 */
public sealed interface LayoutNode {

    /** A split: horizontal or vertical, with divider positions (0..1) between its children. */
    record Branch(boolean vertical, List<Double> dividers, List<LayoutNode> children) implements LayoutNode { }

    /** A tab group: its views in order and which one is selected. */
    record Leaf(int selected, List<Entry> views) implements LayoutNode { }

    /** One view: its registry ID and its source as {@code robot/option} (empty for none). */
    record Entry(String viewId, String source) { }
}
