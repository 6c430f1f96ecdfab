package touchline.ui.render;

import javafx.scene.Scene;
import javafx.scene.layout.StackPane;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static touchline.testing.FxStep.fx;

/** Pixels drawn into the buffer not on screen, then shown: the one on screen is never drawn into. */
class RasterPaneTest {

    private static final int RED = 0xFFFF0000;
    private static final int BLUE = 0xFF0000FF;

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    /** The pixel at (3, 3) as the pane shows it. FX thread. */
    private static int onScreen(RasterPane pane) {
        return pane.snapshot(null, null).getPixelReader().getArgb(3, 3);
    }

    @Test
    void theViewDrawsIntoTheBufferNotOnScreenAndShowsItInTurn() throws Exception {
        fx(() -> {
            RasterPane pane = new RasterPane(() -> { });
            new Scene(new StackPane(pane), 100, 80);
            int[] first = pane.back(10, 8);
            Arrays.fill(first, RED);
            assertNotEquals(RED, onScreen(pane), "nothing shown yet");
            pane.showBack(1);
            assertEquals(RED, onScreen(pane));

            int[] second = pane.back(10, 8);
            assertNotSame(first, second, "the next picture goes into the other buffer");
            Arrays.fill(second, BLUE);
            assertEquals(RED, onScreen(pane), "what is on screen is not drawn into");
            pane.showBack(1);
            assertEquals(BLUE, onScreen(pane));
            assertSame(first, pane.back(10, 8), "and back to the first");

            int[] resized = pane.back(12, 8);
            assertEquals(12 * 8, resized.length, "a new size, new buffers");
            return null;
        });
    }
}
