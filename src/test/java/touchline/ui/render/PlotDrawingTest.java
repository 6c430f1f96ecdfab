package touchline.ui.render;

import javafx.scene.Scene;
import javafx.scene.layout.StackPane;
import javafx.scene.paint.Color;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.model.store.PlotStore;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

/** The plot drawn into its own pixels and shown as one image, its labels rendered once, an axis per unit. */
class PlotDrawingTest {

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    private static PlotDrawing plot() {
        PlotDrawing plot = new PlotDrawing(() -> { });
        StackPane root = new StackPane(plot.node());
        new Scene(root, 400, 300);
        root.applyCss();
        root.layout();
        return plot;
    }

    /** A flat series at y = 1 and a ramp from -1 to 1 over ten seconds. */
    private static List<PlotStore.SeriesData> series() {
        int n = 101;
        double[] x = new double[n];
        double[] flat = new double[n];
        double[] ramp = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = i * 0.1;
            flat[i] = 1;
            ramp[i] = -1 + 2 * i / (double) (n - 1);
        }
        return List.of(new PlotStore.SeriesData("flat", x, flat, n), new PlotStore.SeriesData("ramp", x, ramp, n));
    }

    @Test
    void theSeriesAreDrawnInTheirColoursAndShownOnThePane() throws Exception {
        fx(() -> {
            PlotDrawing plot = plot();
            assertEquals(202, plot.draw(series()));
            javafx.scene.image.Image shown = plot.node().snapshot(null, null); // what the pane shows
            int flat = Raster.opaque(PlotDrawing.PALETTE[0]);
            // the flat series is the top of the data: y = 1 sits 5 % of the range below the plot's top edge
            int column = (int) shown.getWidth() / 2;
            boolean found = false;
            for (int y = 0; y < shown.getHeight() && !found; y++) {
                found = shown.getPixelReader().getArgb(column, y) == flat;
            }
            assertTrue(found, "the first series' colour in the middle column, on the pane");
            return null;
        });
    }

    @Test
    void labelsAreRenderedOnceAndDrawnLeftOfTheAxis() throws Exception {
        fx(() -> {
            LabelSprites labels = new LabelSprites(javafx.scene.text.Font.font(11));
            Raster.Sprite first = labels.of("15 s", Color.WHITE, 1);
            assertSame(first, labels.of("15 s", Color.WHITE, 1), "the same label again: not rendered anew");
            assertNotSame(first, labels.of("15 s", Color.WHITE, 2), "at another scale it is");

            PlotDrawing plot = plot();
            plot.draw(series());
            javafx.scene.image.Image shown = plot.node().snapshot(null, null);
            int background = Raster.opaque(Color.gray(0.12));
            int lit = 0;
            for (int y = 0; y < shown.getHeight(); y++) {
                for (int x = 0; x < 50; x++) { // left of the axis at x = 58: only the y labels are there
                    lit += shown.getPixelReader().getArgb(x, y) != background ? 1 : 0;
                }
            }
            assertTrue(lit > 20, "the y labels' glyphs left of the axis: " + lit + " pixels");
            assertTrue(lit < 50 * shown.getHeight() / 2, "the plot's background around them: " + lit + " pixels lit");
            return null;
        });
    }

    /** Issue 36 item 9: millimetres and a battery's percent each get their own y axis, fitted to their values. */
    @Test
    void eachUnitHasItsOwnYAxis() throws Exception {
        int n = 11;
        double[] x = new double[n];
        double[] mm = new double[n];
        double[] percent = new double[n];
        double[] plain = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = i;
            mm[i] = 1000 + 100 * i;
            percent[i] = 80 + i;
            plain[i] = i;
        }
        List<PlotStore.SeriesData> series = List.of(
                new PlotStore.SeriesData("robot 1 pose:distance_mm", x, mm, n),
                new PlotStore.SeriesData("robot 1 status:batteryPercent", x, percent, n),
                new PlotStore.SeriesData("robot 2 status:batteryPercent", x, percent, n),
                new PlotStore.SeriesData("robot 1 status:x", x, plain, n));
        fx(() -> {
            // the plot's axes for series all in its window, as PlotDrawing.draw makes them
            YAxes axes = new YAxes(series, new int[series.size()], false);
            assertEquals(3, axes.count());
            assertEquals("mm", axes.of(0).unit());
            assertEquals("%", axes.of(1).unit());
            assertEquals(axes.of(1), axes.of(2));
            assertEquals("", axes.of(3).unit());
            assertTrue(axes.of(0).y0() < 1000 && axes.of(0).y1() > 2000 && axes.of(0).y0() > 900, axes.of(0).toString());
            assertTrue(axes.of(1).y0() > 75 && axes.of(1).y1() < 95, axes.of(1).toString());
            assertEquals("1200 mm", axes.of(0).label("1200"));

            assertEquals(4, new YAxes(series, new int[series.size()], true).count(), "one axis per series");
            return null;
        });
    }

    /** A plot of series with no known unit keeps one y axis, as before units were read. */
    @Test
    void seriesOfNoKnownUnitShareOneAxis() throws Exception {
        fx(() -> {
            YAxes axes = new YAxes(series(), new int[2], false);
            assertEquals(1, axes.count());
            assertEquals("", axes.axis(0).unit());
            return null;
        });
    }

    @Test
    void theUnitIsReadFromTheFieldsName() {
        assertEquals("mm", YAxes.unitOf("robot 3 pose:ball.distance_mm"));
        assertEquals("mm", YAxes.unitOf("robot 3 pose:ballDistanceMm"));
        assertEquals("%", YAxes.unitOf("robot 3 status:batteryPercent"));
        assertEquals("%", YAxes.unitOf("robot 3 status:battery"));
        assertEquals("°", YAxes.unitOf("robot 3 head:yaw_deg"));
        assertEquals("", YAxes.unitOf("robot 3 status:comm"));
        assertEquals("", YAxes.unitOf("robot 3 pose:x"));
    }
}
