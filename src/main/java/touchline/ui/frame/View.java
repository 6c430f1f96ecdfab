package touchline.ui.frame;

import javafx.scene.Node;

/**
 * One dockable view. The frame pulse calls {@link #refresh} on the FX thread at most once per
 * frame; a view reads the model there (cheaply when nothing changed) and never receives
 * per-message callbacks.
 */
public interface View {

    Node node();

    /** Pull what changed from the model and update the nodes. FX thread only. */
    void refresh(FrameContext frame);

    /** The view's source (robot and option) for layouts; null for views without one. */
    default ViewSource source() {
        return null;
    }

    /**
     * What a layout keeps of the view beyond its source, as one word (no white space), e.g. the
     * Plot fields view's chosen series; null: the source alone.
     */
    default String layoutState() {
        return null;
    }

    /** Takes back what {@link #layoutState} gave when the layout was saved (ignores what it does not know). */
    default void restoreLayoutState(String state) { }

    default void close() { }
}
