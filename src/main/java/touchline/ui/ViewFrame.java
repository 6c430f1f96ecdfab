package touchline.ui;

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
 */
public final class ViewFrame extends BorderPane {

    private static final Logger LOG = LoggerFactory.getLogger(ViewFrame.class);

    private final String title;
    private final Supplier<View> maker;
    private final Label fault = new Label();
    private final Button reopen = new Button("Reopen");
    private final HBox faultLine = new HBox(8, fault, reopen);
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
        setCenter(v.node());
    }

    @Override
    protected void layoutChildren() {
        super.layoutChildren();
        layOutCaught(); // a resize lays the view out in the scene's pass: keep its faults here too
    }

    private void layOutCaught() {
        if (stopped || getCenter() == null) {
            return;
        }
        try {
            if (getCenter() instanceof javafx.scene.Parent p) {
                p.layout();
            }
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
