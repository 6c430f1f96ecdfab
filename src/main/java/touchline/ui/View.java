package touchline.ui;

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

    default void close() { }
}
