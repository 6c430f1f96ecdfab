package touchline.ui.window;

import javafx.scene.image.ImageView;
import javafx.scene.paint.Color;
import org.junit.jupiter.api.Test;
import software.coley.bentofx.layout.container.DockContainerLeaf;
import touchline.testing.UiTest;


import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Where a dragged tab would land is drawn in the theme's accent, not BentoFX's red: the tab
 * group's own hint, drawn as BentoFX draws it during a drag, read back from its pixels.
 */
@UiTest
class DropHintUiTest {

    private ConsoleWindowFixture ui;

    private Color hint() throws Exception {
        return ui.fx(() -> {
            DockContainerLeaf leaf = (DockContainerLeaf) ui.window.scene().getRoot().lookup(".container-leaf");
            leaf.getCanvas().applyCss();
            leaf.drawCanvasHint(leaf); // the whole group: where a tab dropped in its middle goes
            leaf.getCanvas().commit();
            ImageView view = (ImageView) leaf.getCanvas().getChildrenUnmodifiable().stream()
                    .filter(n -> n instanceof ImageView).findFirst().orElseThrow();
            return view.getImage().getPixelReader().getColor((int) (leaf.getWidth() / 2), (int) (leaf.getHeight() / 2));
        });
    }

    private static void assertColour(int rgb, Color c) {
        int[] want = {rgb >> 16 & 0xff, rgb >> 8 & 0xff, rgb & 0xff};
        double[] got = {c.getRed() * 255, c.getGreen() * 255, c.getBlue() * 255};
        for (int i = 0; i < 3; i++) {
            // the image keeps a light alpha: its colour is rounded through premultiplication
            assertTrue(Math.abs(want[i] - got[i]) <= 4, String.format("#%06x wanted, %s drawn", rgb, c));
        }
        assertTrue(c.getOpacity() > 0 && c.getOpacity() < 1, "a see-through hint: " + c);
    }

    @Test
    void theDropTargetIsTheThemesAccent() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
        ui.await(30, () -> ui.window.scene().getRoot().lookup(".container-leaf") instanceof DockContainerLeaf l
                && l.getWidth() > 0);
        assertColour(0x1f6feb, hint()); // PrimerDark's -color-accent-emphasis
        ui.fxRun(() -> ui.window.setDark(false));
        assertColour(0x0969da, hint()); // PrimerLight's
    }
}
