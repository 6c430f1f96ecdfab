package touchline.ui.window;

import javafx.scene.Node;
import javafx.scene.layout.Region;
import javafx.scene.paint.Color;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.UiTest;
import touchline.ui.window.LayoutNode;
import touchline.ui.plots.PlotView;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.ViewFrame;

/**
 * What keeps the window's software drawing small (issue 14, docs/archive/benchmarks-sessions.md "Twelfth
 * session"): no view is drawn into a cached image first, a canvas's repaint starts at its own
 * opaque pane, and no transparent background is filled where views repaint.
 */
@UiTest
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
    /**
     * A fill that is not opaque costs the software renderer a blend of every pixel it covers each
     * time anything under it changes; the dock's split panes lay three of them under the demo
     * layout's views (two thirds of the render thread, docs/archive/benchmarks-sessions.md "Fourteenth session").
     * Only buttons that light up under the mouse may have one.
     */
    @Test
    void noRegionOfTheDemoLayoutFillsATransparentBackground() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
            ui.await(10, () -> ui.window.shell().openViews().size() == 7
                    && ui.window.shell().openViews().stream().filter(v -> v.view().node().getScene() != null).count() >= 5);
            ui.fxRun(() -> {
                List<String> seeThrough = new java.util.ArrayList<>();
                javafx.scene.Scene scene = ui.window.shell().openViews().stream().map(v -> v.view().node().getScene())
                        .filter(java.util.Objects::nonNull).findFirst().orElseThrow();
                collectSeeThrough(scene.getRoot(), seeThrough);
                assertEquals(List.of(), seeThrough, "regions filling a background that is not opaque");
            });
        }
    }

    private static void collectSeeThrough(Node node, List<String> out) {
        if (!node.isVisible()) {
            return;
        }
        if (node instanceof Region r && r.getBackground() != null
                && !node.getStyleClass().contains("close-button") && !node.getStyleClass().contains("menu-button")
                && !node.getStyleClass().contains("arrow")) {
            for (var fill : r.getBackground().getFills()) {
                if (!(fill.getFill() instanceof Color c) || !c.isOpaque()) {
                    out.add(node.getClass().getSimpleName() + node.getStyleClass() + " " + fill.getFill());
                }
            }
        }
        if (node instanceof javafx.scene.Parent p) {
            for (Node child : p.getChildrenUnmodifiable()) {
                collectSeeThrough(child, out);
            }
        }
    }
}
