package touchline.ui;

import javafx.scene.Node;
import javafx.scene.layout.Region;
import javafx.scene.paint.Color;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.ui.layout.LayoutNode;
import touchline.ui.views.PlotView;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What keeps the window's software drawing small (issue 14, docs/benchmarks.md "Twelfth
 * session"): no view is drawn into a cached image first, a canvas's repaint starts at its own
 * opaque pane, and no transparent background is filled where views repaint.
 */
@Tag("ui")
class DrawingCostUiTest {

    @TempDir
    Path layouts;

    @Test
    void viewsAreNotCachedCanvasPanesAreOpaqueAndScrollFramesFillNothing() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("plot", ""))))));
            PlotView plot = ui.view(PlotView.class);
            assertNotNull(plot);
            ui.await(10, () -> plot.node().getScene() != null && plot.node().getParent() != null
                    && ui.window.shell().openViews().iterator().next().frame().lookup(".viewport") != null);
            ui.fxRun(() -> {
                ViewFrame frame = ui.window.shell().openViews().iterator().next().frame();
                Region scroller = (Region) frame.lookup(".view-scroller");
                Node viewport = frame.lookup(".viewport");
                assertFalse(viewport.isCache(), "the view's scroll pane draws it directly, not into an image first");
                assertTrue(scroller.getBackground() == null || scroller.getBackground().isEmpty(),
                        "the frame around a view fills nothing (a transparent fill costs a full pass)");
                assertTrue(((Region) viewport).getBackground() == null || ((Region) viewport).getBackground().isEmpty());

                Region pane = (Region) plot.node().lookup(".canvas-pane");
                assertNotNull(pane, "the plot's canvas sits on its pane");
                var fill = pane.getBackground().getFills().get(0);
                assertTrue(fill.getFill() instanceof Color c && c.isOpaque(), "the canvas pane is opaque: " + fill.getFill());
                assertEquals(-1, fill.getInsets().getTop(), "and reaches a pixel beyond its bounds");
            });
        }
    }
}
