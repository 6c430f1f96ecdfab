package touchline.ui.frame;

import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.HashSet;
import java.util.Set;
import java.util.function.Supplier;

/**
 * Holds one view in its tab and keeps the view's faults inside it. The frame pulse pulls the
 * view through {@link #pull}: the refresh and then the layout of the view's nodes both run
 * here, inside a catch, so an exception (a table cell that throws, say) is shown as a red
 * line at the top of this view, logged once, and never reaches the scene's layout pass.
 * JavaFX leaves every ancestor of a node whose layout threw unable to lay out again, which
 * once froze every other view of the window while plot and field kept drawing.
 * <p>
 * A refresh that throws is asked again next frame, and the line goes away once it succeeds.
 * A layout that threw leaves the view's own nodes stuck, so the view stops and offers to
 * reopen it (a fresh instance with the same source).
 * <p>
 * The frame also keeps a view inside its pane: a view larger than the pane scrolls instead
 * of covering the menu or pushing the status bar out of the window, and buttons keep their
 * full labels rather than shrinking to "…".
 */
public final class ViewFrame extends BorderPane {

    private static final Logger LOG = LoggerFactory.getLogger(ViewFrame.class);
    /** How often (in frames, twice a second at 60 fps) buttons added since are given their full width. */
    private static final int LABEL_CHECK_FRAMES = 30;

    private final String title;
    private final Supplier<View> maker;
    private final Label fault = new Label();
    private final Button reopen = new Button("Reopen");
    private final HBox faultLine = new HBox(8, fault, reopen);
    private javafx.scene.control.ScrollPane scroller;
    private final Set<String> logged = new HashSet<>();
    private View view;
    private boolean stopped;
    private boolean failing;

    public ViewFrame(String title, Supplier<View> maker) {
        this.title = title;
        this.maker = maker;
        getStyleClass().add("view-frame");
        fault.getStyleClass().add("view-fault");
        fault.setWrapText(true);
        fault.setMaxWidth(Double.MAX_VALUE);
        HBox.setHgrow(fault, Priority.ALWAYS);
        faultLine.getStyleClass().add("view-fault-line");
        reopen.getStyleClass().add("view-reopen");
        reopen.setOnAction(e -> reopen());
        reopen.setVisible(false);
        reopen.setManaged(false);
        setMinSize(0, 0);
        javafx.scene.shape.Rectangle clip = new javafx.scene.shape.Rectangle();
        clip.widthProperty().bind(widthProperty());
        clip.heightProperty().bind(heightProperty());
        setClip(clip);
        show(maker.get());
    }

    public View view() {
        return view;
    }

    /** The reason shown at the top of the view, or "" when the view works. */
    public String fault() {
        return getTop() == null ? "" : fault.getText();
    }

    /** True when the view's layout failed and it no longer updates until reopened. */
    public boolean stopped() {
        return stopped;
    }

    /** One frame: the view pulls from the model, then its nodes are laid out, both caught. */
    public void pull(FrameContext frame) {
        if (stopped) {
            return;
        }
        try {
            view.refresh(frame);
            if (frame.frame() % LABEL_CHECK_FRAMES == 0) {
                keepLabels(view.node()); // buttons a view adds later (robot rows, say)
            }
            if (failing) {
                failing = false;
                setTop(null);
            }
        } catch (RuntimeException e) {
            failing = true;
            report("failed to refresh", e);
        }
        layOutCaught();
    }

    /** A fresh instance of the view in place of the stopped one. */
    public void reopen() {
        view.close();
        stopped = false;
        failing = false;
        logged.clear();
        show(maker.get());
    }

    private void show(View v) {
        view = v;
        setTop(null);
        reopen.setVisible(false);
        reopen.setManaged(false);
        keepLabels(v.node());
        // a new scroller each time: after a layout fault its own nodes are stuck as well
        scroller = new javafx.scene.control.ScrollPane(v.node());
        scroller.setFitToWidth(true);
        scroller.setFitToHeight(true);
        scroller.getStyleClass().add("view-scroller");
        uncacheViewport(scroller);
        setCenter(scroller);
    }

    /**
     * The scroll pane's skin caches its viewport as an image: a view that changes is then drawn whole
     * into that image and the image into the window, every frame (58 % of the render thread's
     * time with the demo layout in software, docs/archive/benchmarks-sessions.md "Twelfth session"). Without the cache only what changed is drawn.
     */
    private static void uncacheViewport(javafx.scene.control.ScrollPane pane) {
        pane.skinProperty().addListener((o, was, skin) -> {
            javafx.scene.Node viewport = skin == null ? null : pane.lookup(".viewport");
            if (viewport != null) {
                viewport.setCache(false);
            }
        });
    }

    /** Buttons never shrink below their label: the pane scrolls instead (nodes the view has now). */
    private static void keepLabels(javafx.scene.Node node) {
        if (node instanceof javafx.scene.control.IndexedCell<?>) {
            return; // a table's or list's cells: their rows are the data, not the view's words
        }
        if (node instanceof javafx.scene.control.ButtonBase b && b.getText() != null && !b.getText().isEmpty()
                && b.getMinWidth() == USE_COMPUTED_SIZE) {
            b.setMinWidth(USE_PREF_SIZE);
        }
        if (node instanceof Label l && l.getTooltip() == null && !l.getProperties().containsKey(WHOLE_TEXT)) {
            wholeTextWhenCut(l);
        } else if (node instanceof Label l && l.getProperties().get(WHOLE_TEXT) instanceof javafx.scene.control.Tooltip whole
                && (l.getTooltip() == null || l.getTooltip() == whole)) {
            // the text's own width can change without the label's (its font or style applied later)
            l.setTooltip(cut(l) ? whole : null);
        }
        // an empty table's or list's words join the scene only with its skin: reached here from the start
        if (node instanceof javafx.scene.control.TableView<?> t && t.getPlaceholder() != null) {
            keepLabels(t.getPlaceholder());
        }
        if (node instanceof javafx.scene.control.ListView<?> list && list.getPlaceholder() != null) {
            keepLabels(list.getPlaceholder());
        }
        // a split pane's and a scroll pane's contents join the scene graph only with their skins: a view
        // whose root is a split pane (the robots table above its notes) is reached from the start too
        if (node instanceof javafx.scene.control.SplitPane split) {
            split.getItems().forEach(ViewFrame::keepLabels);
        }
        if (node instanceof javafx.scene.control.ScrollPane scroll && scroll.getContent() != null) {
            keepLabels(scroll.getContent());
        }
        if (node instanceof javafx.scene.Parent p) {
            for (javafx.scene.Node child : p.getChildrenUnmodifiable()) {
                keepLabels(child);
            }
        }
    }

    /** The key under which a label keeps the tooltip {@link #wholeTextWhenCut} gives it. */
    private static final String WHOLE_TEXT = "touchline.wholeText";

    /**
     * A status text cut to "…" in a narrow pane shows the whole of it, as it changes, under the
     * pointer; a text shown whole has no tooltip (it would only repeat itself). Followed as the
     * label's width and text change, not only when a pass looks.
     */
    private static void wholeTextWhenCut(Label l) {
        javafx.scene.control.Tooltip whole = new javafx.scene.control.Tooltip();
        whole.textProperty().bind(l.textProperty());
        whole.setWrapText(true);
        whole.setMaxWidth(640);
        l.getProperties().put(WHOLE_TEXT, whole);
        javafx.beans.InvalidationListener follow = o -> {
            if (l.getTooltip() == null || l.getTooltip() == whole) {
                l.setTooltip(cut(l) ? whole : null);
            }
        };
        l.widthProperty().addListener(follow);
        l.textProperty().addListener(follow);
        l.fontProperty().addListener(follow); // the stylesheet's font, applied after the first layout, widens the text
        follow.invalidated(null);
    }

    /** Whether a label shows less than its text (cut to "…"). */
    static boolean cut(Label l) {
        return l.isVisible() && l.getText() != null && !l.getText().isEmpty() && l.getWidth() > 0
                && l.getWidth() + 0.5 < l.prefWidth(-1);
    }

    @Override
    protected void layoutChildren() {
        super.layoutChildren();
        layOutCaught(); // a resize lays the view out in the scene's pass: keep its faults here too
    }

    private void layOutCaught() {
        if (stopped) {
            return;
        }
        try {
            scroller.layout();
        } catch (RuntimeException e) {
            stopped = true;
            reopen.setVisible(true);
            reopen.setManaged(true);
            report("stopped updating", e);
        }
    }

    private void report(String what, RuntimeException e) {
        String reason = e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage());
        fault.setText(title + " " + what + " — " + reason + (stopped ? " (the other views go on)" : ""));
        if (getTop() != faultLine) {
            setTop(faultLine);
        }
        if (logged.add(what + e)) {
            LOG.warn("view {} {}: {}", title, what, e.toString(), e);
        }
    }
}
