package touchline.ui.window;

import javafx.scene.control.TextArea;
import javafx.scene.input.KeyCode;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.model.store.StoreEnvelopes;
import touchline.proto.Fumanoid;
import touchline.testing.UiTest;
import touchline.transport.Envelope;
import touchline.ui.plots.ImageDataView;
import touchline.ui.plots.PlotView;
import touchline.ui.consoles.RawDataView;
import touchline.ui.field.RegionOverlayView;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.View;
import touchline.ui.frame.ViewSource;

/**
 * Bad input reaching the views through the Envelope stream (as a replay or a broken robot would
 * deliver it): each view shows what it can, says what it could not, and the next good input
 * shows again.
 */
@UiTest
class BadInputUiTest {

    private static final int ROBOT = 50;
    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        publish(StoreEnvelopes.status(now(), ROBOT));
    }

    private long now() {
        return ui.console.field().clock().nowMicros();
    }

    private void publish(Envelope e) {
        ui.console.field().bus().accept(e);
    }

    private String status(View view) throws Exception {
        return ui.fx(() -> ui.robot.from(view.node()).lookup(".source-status").queryLabeled().getText());
    }

    @Test
    void anOptionOfUnknownKindIsMarkedAndItsDataShownAsText() throws Exception {
        publish(StoreEnvelopes.optionList(now(), ROBOT, "team.secret", 77));
        publish(StoreEnvelopes.text(now(), ROBOT, "team.secret", "forty-two"));
        ui.fxRun(() -> ui.window.open("options", ViewSource.NONE));
        ui.await(10, () -> ui.optionCell(ROBOT, "team.secret") != null
                && ui.optionCell(ROBOT, "team.secret").getText().contains("unknown kind 77"));
        ui.selectOption(ROBOT, "team.secret");
        ui.robot.type(KeyCode.ENTER);
        ui.await(10, () -> ui.view(RawDataView.class) != null);
        RawDataView raw = ui.view(RawDataView.class);
        ui.await(10, () -> ui.robot.from(raw.node()).lookup("#raw-text").queryAs(TextArea.class).getText()
                .contains("forty-two"));
        // a status line changes at most twice a second (PacedText): the newest one shows within half a second
        ui.await(10, () -> status(raw).contains("unknown data kind"));
    }

    @Test
    void aPlotSkipsNaNAndDecimatesABurst() throws Exception {
        ui.fxRun(() -> ui.window.open("plot", new ViewSource(ROBOT, "bad.plot")));
        PlotView plot = ui.view(PlotView.class);
        double[] burst = new double[10_000];
        for (int i = 0; i < burst.length; i++) {
            burst[i] = i % 2 == 0 ? Double.NaN : Math.sin(i / 300.0);
        }
        publish(StoreEnvelopes.plot(now(), ROBOT, "bad.plot", "wobble", burst));
        publish(StoreEnvelopes.plot(now() + 1000, ROBOT, "bad.plot", "wobble", 0.25));
        ui.await(10, () -> ui.plottedPoints(plot) > 0 && status(plot).contains("NaN") && status(plot).contains("decimated"));
        String s = status(plot);
        assertTrue(s.contains("5000 NaN/infinite skipped"), s);
        assertTrue(s.contains("1 bursts decimated"), s);
        // at most four points per pixel column are drawn: ColumnDecimationTest, the plot's own decimation
    }

    @Test
    void aPlotWithNoNewDataDoesNotRedraw() throws Exception {
        ui.fxRun(() -> ui.window.open("plot", new ViewSource(ROBOT, "calm.plot")));
        PlotView plot = ui.view(PlotView.class);
        publish(StoreEnvelopes.plot(now(), ROBOT, "calm.plot", "a", 1.0, 2.0, 3.0));
        ui.await(10, () -> ui.plottedPoints(plot) == 3);
        // The first status line can change the layout once, and the canvas' resize is drawn
        // in the next frame: let three frames pass, then count.
        long settled = ui.fx(() -> ui.window.pulse().frames());
        ui.await(10, () -> ui.window.pulse().frames() > settled + 3);
        PlotRedraws counted = ui.fx(() -> new PlotRedraws(plot.node()));
        long frame = ui.fx(() -> ui.window.pulse().frames());
        ui.await(10, () -> ui.window.pulse().frames() > frame + 10);
        // a resize is a reason to redraw, ten frames without new data are not
        long redraws = ui.fx(counted::draws);
        long resized = ui.fx(counted::resizes);
        assertTrue(redraws <= resized, "redrawn " + redraws + " times without new data, resized " + resized + " times");
        publish(StoreEnvelopes.plot(now(), ROBOT, "calm.plot", "a", 4.0));
        ui.await(10, () -> counted.draws() > redraws);
    }

    @Test
    void regionsOutsideTheFrameAreClippedOrCountedNotDrawn() throws Exception {
        ui.fxRun(() -> ui.window.open("regions", new ViewSource(ROBOT, "bad.region")));
        RegionOverlayView overlay = ui.view(RegionOverlayView.class);
        publish(StoreEnvelopes.regions(now(), ROBOT, "bad.region",
                new int[] {10, 10, 40, 30}, new int[] {150, 100, 220, 180}, new int[] {500, 500, 600, 600}));
        ui.await(10, () -> status(overlay).contains("regions") && status(overlay).contains("outside"));
        String s = status(overlay);
        assertTrue(s.contains("2 regions"), s);
        assertTrue(s.contains("1 clipped"), s);
        assertTrue(s.contains("1 outside the frame"), s);
    }

    @Test
    void anImageThatDoesNotDecodeIsMarkedAndTheNextGoodOneShows() throws Exception {
        ui.fxRun(() -> ui.window.open("image", new ViewSource(ROBOT, "bad.image")));
        ImageDataView image = ui.view(ImageDataView.class);
        publish(StoreEnvelopes.image(now(), ROBOT, "bad.image", 0, 0, Fumanoid.ImageFormat.JPEG_VALUE,
                new byte[] {(byte) 0xFF, (byte) 0xD8, 1, 2, 3}));
        ui.await(10, () -> status(image).contains("not decoded"));
        publish(StoreEnvelopes.image(now(), ROBOT, "bad.image", 40, 30, Fumanoid.ImageFormat.RGB888_VALUE, new byte[100]));
        ui.await(10, () -> status(image).contains("needs 3600 bytes, got 100"));
        publish(StoreEnvelopes.image(now(), ROBOT, "bad.image", 4, 3, Fumanoid.ImageFormat.GRAY8_VALUE, new byte[12]));
        ui.await(10, () -> status(image).startsWith("4×3 GRAY8"));
        ui.await(10, () -> status(image).contains("2 frames did not decode"));
    }
}
