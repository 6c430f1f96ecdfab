package touchline.ui.window;

import javafx.animation.AnimationTimer;
import javafx.stage.Stage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.store.StoreEnvelopes;
import touchline.proto.Fumanoid;
import touchline.testing.UiTest;
import touchline.transport.Envelope;
import touchline.ui.window.LayoutCodec;
import touchline.ui.window.LayoutNode;
import touchline.ui.plots.FieldPlotView;
import touchline.ui.field.FieldView;
import touchline.ui.plots.PlotView;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.FramePulse;
import touchline.ui.frame.ViewSource;

/**
 * Light on the laptop (issue 14, item 9): a view redraws only when what it shows changed, the
 * frame pulse stops when nothing changed and starts again on the next change, and a minimised
 * window does no frame work. Also the Plot fields view's series kept with the layout, and F1 in
 * a window other than the main one.
 */
@UiTest
class IdleWindowUiTest {

    private static final int ROBOT = 61;
    @TempDir
    Path layouts;

    private static Envelope status(ConsoleWindowFixture ui, float x) {
        return StoreEnvelopes.in(ui.console.field().clock().nowMicros(), ROBOT, "status", Fumanoid.Message.newBuilder()
                .setRobotID(ROBOT).setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13)
                        .setBatteryPercent(80).setRobotPosition(Fumanoid.Position.newBuilder().setX(x).setY(0))
                        .build()).build());
    }

    /** A window showing only the field, robot {@link #ROBOT} drawn on it at x = 100. */
    private static FieldView fieldWith(ConsoleWindowFixture ui) throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                List.of(new LayoutNode.Entry("field", ""))))));
        ui.console.field().bus().accept(status(ui, 100));
        FieldView field = ui.view(FieldView.class);
        ui.await(10, () -> ui.robotsOnTheField() == 1);
        return field;
    }

    @Test
    void aViewRedrawsOnlyWhenItsDataChangedAndTheIdleWindowWakesOnTheNext() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            ui.fxRun(() -> ui.window.shell().restore(List.of()));
            ui.fxRun(() -> ui.window.open("plot", new ViewSource(ROBOT, "calm.plot")));
            PlotView plot = ui.view(PlotView.class);
            FramePulse pulse = ui.window.pulse();
            ui.console.field().bus().accept(StoreEnvelopes.plot(ui.console.field().clock().nowMicros(), ROBOT, "calm.plot", "a", 1, 2, 3));
            ui.await(10, () -> ui.plottedPoints(plot) == 3);
            // quiet from here: the pulse pulls a few catch-up frames, then stops and says so
            ui.await(30, () -> !pulse.running());
            assertTrue(ui.fx(() -> ui.robot.lookup("#status-bar").queryAs(StatusBar.class).getChildren().stream()
                    .anyMatch(n -> n instanceof javafx.scene.control.Label l && "idle".equals(l.getText()))));
            PlotRedraws counted = ui.fx(() -> new PlotRedraws(plot.node()));
            long workFrames = ui.fx(pulse::workFrames);
            // a datagram that moves the robot registry but not the plot's data: the idle watch wakes
            // the pulse, the views pull, the plot does not redraw (a resize would be a reason to)
            ui.console.field().bus().accept(StoreEnvelopes.text(ui.console.field().clock().nowMicros(), ROBOT, "demo.text", "hello"));
            ui.await(10, () -> pulse.workFrames() > workFrames);
            ui.await(30, () -> !pulse.running());
            long redraws = ui.fx(counted::draws);
            long resized = ui.fx(counted::resizes);
            assertTrue(redraws <= resized, "redrawn " + redraws + " times without new data, resized " + resized + " times");
            // new data for the plot: woken again, and drawn
            ui.console.field().bus().accept(StoreEnvelopes.plot(ui.console.field().clock().nowMicros(), ROBOT, "calm.plot", "a", 4));
            ui.await(10, () -> counted.draws() > redraws); // (older points may have left its 10-s window)
        }
    }

    @Test
    void aRobotThatMovesMovesItsShapeAndLeavesTheFieldAsPainted() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            FieldView field = fieldWith(ui);
            javafx.scene.Node shape = ui.fx(() -> ((javafx.scene.Parent) ui.robot.lookup("#field-robots").query())
                    .getChildrenUnmodifiable().get(0));
            double at100 = ui.fx(shape::getLayoutX);
            long fieldPaints = ui.fx(field::fieldPaints);
            ui.console.field().bus().accept(status(ui, 900)); // 800 mm towards the opponent goal
            ui.await(10, () -> ui.fx(shape::getLayoutX) > at100 + 1); // the robot drawn where it is now
            assertEquals(fieldPaints, (long) ui.fx(field::fieldPaints), "the field itself is not painted again");
            assertEquals(1, (int) ui.fx(ui::robotsOnTheField));
        }
    }

    @Test
    void aMinimisedWindowDoesNoFrameWorkAndCatchesUpWhenShownAgain() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            fieldWith(ui);
            FramePulse pulse = ui.window.pulse();
            Stage stage = (Stage) ui.window.scene().getWindow();
            ui.fxRun(() -> stage.setIconified(true));
            ui.await(10, () -> stage.isIconified() && !pulse.running());
            long frames = ui.fx(pulse::frames);
            javafx.scene.Node shape = ui.fx(() -> ((javafx.scene.Parent) ui.robot.lookup("#field-robots").query())
                    .getChildrenUnmodifiable().get(0));
            double at100 = ui.fx(shape::getLayoutX);
            ui.console.field().bus().accept(status(ui, 900)); // the robot moves while the window is minimised
            // JavaFX goes on pulsing (a timer of the test's own counts 60 pulses): the console's pulse does nothing
            AtomicLong otherPulses = new AtomicLong();
            AnimationTimer counter = new AnimationTimer() {
                @Override
                public void handle(long now) {
                    otherPulses.incrementAndGet();
                }
            };
            ui.fxRun(counter::start);
            ui.await(30, () -> otherPulses.get() >= 60 && ui.console.field().robots().robot(ROBOT)
                    .map(r -> r.x() == 900).orElse(false));
            ui.fxRun(counter::stop);
            assertEquals(frames, (long) ui.fx(pulse::frames), "no frame while minimised");
            assertEquals(at100, (double) ui.fx(shape::getLayoutX), "the robot still drawn where it was");
            assertFalse(ui.fx(pulse::running));
            ui.fxRun(() -> stage.setIconified(false));
            ui.await(10, () -> shape.getLayoutX() > at100 + 1); // drawn where it is now
        }
    }

    @Test
    void thePlotFieldsSeriesAreSavedWithTheLayoutAndComeBackOnceTheirKindIsSeen() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry("field-plot", ""))))));
            FieldPlotView plot = ui.view(FieldPlotView.class);
            ui.console.field().bus().accept(status(ui, 100));
            ui.await(10, () -> plot.fields().add(ROBOT, "status:batteryPercent"));
            assertTrue(ui.fx(() -> plot.fields().add(ROBOT, "status:robotPosition.x")));
            ui.fxRun(() -> {
                try {
                    ui.window.saveLayout("plots");
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            });
            String saved = new LayoutCodec().write(ui.window.layouts().load("plots").orElseThrow());
            assertTrue(saved.contains("view field-plot series=" + ROBOT + ":status:batteryPercent;" + ROBOT
                    + ":status:robotPosition.x;"), saved);

            ui.fxRun(() -> ui.window.shell().restore(List.of()));
            assertTrue(ui.fx(() -> ui.window.loadLayout("plots")));
            FieldPlotView restored = ui.view(FieldPlotView.class);
            assertTrue(restored != plot, "a new view from the layout");
            // the new view has seen no status yet: the series wait for their kind, and are kept meanwhile
            assertTrue(ui.fx(restored::layoutState).contains(ROBOT + ":status:batteryPercent;"));
            ui.console.field().bus().accept(status(ui, 200));
            ui.await(10, () -> restored.fields().series().size() == 2);
            assertEquals(List.of("robot " + ROBOT + " status:batteryPercent", "robot " + ROBOT + " status:robotPosition.x"),
                    ui.fx(() -> restored.fields().series().stream().map(s -> s.name()).toList()));
        }
    }

    @Test
    void f1InTheQuickOpenWindowGivesEveryViewsHelp() throws Exception {
        try (ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts)) {
            Stage quick = ui.fx(() -> new QuickOpen(ui.window.context(), ui.window.places()).show(ui.window.scene().getWindow()));
            ui.fxRun(() -> {
                quick.requestFocus();
                quick.getScene().lookup("#quick-open-filter").requestFocus();
            });
            ui.await(10, () -> quick.isFocused() && quick.getScene().getFocusOwner() != null);
            ui.robot.type(javafx.scene.input.KeyCode.F1);
            ui.await(10, () -> javafx.stage.Window.getWindows().stream().anyMatch(w -> w instanceof Stage s
                    && "Help — Views".equals(s.getTitle()) && s.isShowing()));
            String text = ui.fx(() -> javafx.stage.Window.getWindows().stream()
                    .filter(w -> w instanceof Stage s && "Help — Views".equals(s.getTitle())).findFirst()
                    .map(w -> ((javafx.scene.control.TextArea) w.getScene().lookup("#help-text")).getText()).orElse(""));
            assertTrue(text.contains(ui.window.registry().byId("network").orElseThrow().help()), text);
        }
    }
}
