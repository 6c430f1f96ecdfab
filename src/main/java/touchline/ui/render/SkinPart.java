package touchline.ui.render;

import javafx.scene.Node;
import javafx.scene.Parent;

import java.util.function.Predicate;

/**
 * A node of a control's skin (its flow, a scroll bar, the header's background), found by a selector
 * once and kept: {@link Node#lookup} parses its selector and walks the control's nodes at every call,
 * which the views did every frame (docs/archive/benchmarks-sessions.md, "Nineteenth session"). Found again when the
 * node left the control (a new skin); {@code null} while the control has none.
 *
 * @param <T> the node's type
 */
public final class SkinPart<T extends Node> {

    private final Parent control;
    private final String selector;
    private final Class<T> type;
    private final Predicate<? super T> which;
    private T found;

    public SkinPart(Parent control, String selector, Class<T> type, Predicate<? super T> which) {
        this.control = control;
        this.selector = selector;
        this.type = type;
        this.which = which;
    }

    public SkinPart(Parent control, String selector, Class<T> type) {
        this(control, selector, type, n -> true);
    }

    /** The node, or null while the control has none. */
    public T get() {
        if (found != null && inside(found)) {
            return found;
        }
        found = null;
        for (Node n : control.lookupAll(selector)) {
            if (type.isInstance(n) && which.test(type.cast(n))) {
                found = type.cast(n);
                break;
            }
        }
        return found;
    }

    private boolean inside(Node n) {
        for (Node p = n; p != null; p = p.getParent()) {
            if (p == control) {
                return true;
            }
        }
        return false;
    }
}
