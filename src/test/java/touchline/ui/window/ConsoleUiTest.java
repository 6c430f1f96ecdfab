package touchline.ui.window;

import javafx.scene.control.TableView;
import javafx.scene.input.KeyCode;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.model.RobotSnapshot;
import touchline.testing.UiTest;
import touchline.ui.render.LiveRows;
import touchline.testing.RobotProcess;
import touchline.ui.window.LayoutNode;
import touchline.ui.plots.PlotView;
import touchline.ui.field.RegionOverlayView;

import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.ViewSource;

/** The real console window (headless) against the real simulated robot. */
@UiTest
@Tag("integration")
class ConsoleUiTest {

    private ConsoleWindowFixture ui;

    private static void assumeRobot() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }

    /** The Robots view's table, once it is in the scene. */
    @SuppressWarnings("unchecked")
    private TableView<LiveRows.Row<RobotSnapshot>> robotTable() {
        return ui.robot.lookup("#robot-table").queryAs(TableView.class);
    }

    @Test
    void aRobotAppearsInTheRobotView() throws Exception {
        assumeRobot();
        try (RobotProcess robot = RobotProcess.robot(7, ui.port()).start()) {
            ui.fxRun(() -> ui.window.open("robots", ViewSource.NONE));
            ui.await(15, () -> robotTable().getItems().stream().map(LiveRows.Row::value)
                    .anyMatch(r -> r.id() == 7 && r.online() && r.teamId() == 13));
        }
    }

    /** A selected row shows it: the tables' one-fill row style must not hide the theme's selection. */
    @Test
    void theSelectedRobotsRowLooksSelected() throws Exception {
        assumeRobot();
        try (RobotProcess robot = RobotProcess.robot(7, ui.port()).start()) {
            ui.fxRun(() -> ui.window.open("robots", ViewSource.NONE));
            ui.await(15, () -> robotTable().getItems().size() == 1 && firstRow() != null);
            javafx.scene.paint.Paint plain = ui.fx(() -> firstRow().getBackground().getFills().get(0).getFill());
            ui.fxRun(() -> {
                robotTable().requestFocus();
                robotTable().getSelectionModel().select(0);
            });
            ui.await(15, () -> firstRow().isSelected()
                    && !firstRow().getBackground().getFills().get(0).getFill().equals(plain));
        }
    }

    /** The robot table's first row on screen, or null before it is laid out. */
    private javafx.scene.control.TableRow<?> firstRow() {
        return robotTable().lookupAll(".table-row-cell").stream()
                .map(n -> (javafx.scene.control.TableRow<?>) n)
                .filter(r -> r.getIndex() == 0 && !r.isEmpty() && r.getBackground() != null)
                .findFirst().orElse(null);
    }

    /**
     * A robot's changing texts change its cells, never the table's list of rows: any change to
     * that list makes JavaFX re-style and lay out every cell of the table, twice a second.
     */
    @Test
    void theRobotTableUpdatesItsCellsWithoutTouchingItsRows() throws Exception {
        assumeRobot();
        try (RobotProcess robot = RobotProcess.robot(7, ui.port()).start()) {
            ui.fxRun(() -> ui.window.open("robots", ViewSource.NONE));
            ui.await(15, () -> robotTable().getItems().size() == 1);
            java.util.List<String> listChanges = new java.util.concurrent.CopyOnWriteArrayList<>();
            LiveRows.Row<RobotSnapshot> row = ui.fx(() -> {
                robotTable().getItems().addListener(
                        (javafx.collections.ListChangeListener<LiveRows.Row<RobotSnapshot>>) c -> listChanges.add(c.toString()));
                return robotTable().getItems().get(0);
            });
            int onlineFor = ui.fx(() -> robotTable().getColumns().stream().map(c -> c.getText()).toList().indexOf("Online for"));
            String first = ui.fx(() -> row.text(onlineFor).getValue());
            ui.await(15, () -> !row.text(onlineFor).getValue().equals(first)); // "Online for" moved on a second
            ui.fxRun(() -> {
                assertEquals(java.util.List.of(), listChanges, "the same robot: the rows stay as they are");
                assertSame(row, robotTable().getItems().get(0));
            });
        }
    }

    @Test
    void togglingAnOptionInTheTreeShowsItsDataInTheVisualisation() throws Exception {
        assumeRobot();
        try (RobotProcess robot = RobotProcess.robot(3, ui.port()).start()) {
            ui.fxRun(() -> ui.window.open("options", ViewSource.NONE));
            ui.selectOption(3, "demo.plotter");
            ui.robot.type(KeyCode.SPACE);
            ui.await(10, () -> ui.console.field().options().options(3).option("demo.plotter").orElseThrow().wanted());
            ui.await(10, () -> ui.console.field().options().options(3).option("demo.plotter").orElseThrow().streaming());
            ui.robot.doubleClickOn(ui.fx(() -> ui.optionCell(3, "demo.plotter")));
            ui.await(10, () -> ui.view(PlotView.class) != null);
            PlotView plot = ui.view(PlotView.class);
            assertEquals(new ViewSource(3, "demo.plotter"), ui.fx(plot::source));
            ui.await(10, () -> ui.plottedPoints(plot) > 0);

            // the same with the keyboard only: select, Space, Enter
            ui.fxRun(() -> ui.window.open("options", ViewSource.NONE));
            ui.selectOption(3, "havimo.region");
            ui.robot.type(KeyCode.SPACE);
            ui.await(10, () -> ui.console.field().options().options(3).option("havimo.region").orElseThrow().streaming());
            ui.robot.type(KeyCode.ENTER);
            ui.await(10, () -> ui.view(RegionOverlayView.class) != null);
            RegionOverlayView overlay = ui.view(RegionOverlayView.class);
            ui.await(10, () -> ui.robot.from(overlay.node()).lookup(".source-status").queryLabeled().getText()
                    .contains("regions"));
        }
    }

    @Test
    void aLayoutIsSavedAndRestored() throws Exception {
        ui.fxRun(() -> {
            ui.window.shell().restore(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("robots", "")))));
            ui.window.open("network", ViewSource.NONE);
            ui.window.open("plot", new ViewSource(4, "demo.plotter"));
            ui.window.open("regions", new ViewSource(5, "havimo.region"));
        });
        Set<String> before = openViews();
        ui.fxRun(() -> {
            try {
                ui.window.saveLayout("match day");
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
            ui.window.shell().restore(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry("field", "")))));
        });
        assertEquals(Set.of("field"), openViews());
        assertTrue(ui.fx(() -> ui.window.loadLayout("match day")));
        assertEquals(before, openViews());
        assertTrue(before.contains("plot 4/demo.plotter"), before.toString());
        assertTrue(ui.window.layouts().names().contains("match day"));
    }

    @Test
    void aLayoutWithAMissingViewOrRobotStillOpens() throws Exception {
        java.nio.file.Files.writeString(ui.layoutDir().resolve("old.layout"), """
                touchline-layout 1
                window
                 branch vertical 0.5
                  leaf 0
                   view view-from-the-future
                   view plot 99/demo.plotter
                  gadget 3
                   view robots
                  leaf 7
                   view options
                """);
        assertTrue(ui.fx(() -> ui.window.loadLayout("old")));
        assertEquals(Set.of("plot 99/demo.plotter", "options"), openViews());
        PlotView plot = ui.view(PlotView.class);
        ui.await(5, () -> ui.robot.from(plot.node()).lookup(".source-status").queryLabeled().getText()
                .contains("waiting for data from robot 99"));
    }

    private Set<String> openViews() throws Exception {
        return ui.fx(() -> ui.window.shell().openViews().stream().map(v -> {
            ViewSource s = v.view().source();
            return v.spec().id() + (s != null && s.isSet() ? " " + s.encode() : "");
        }).collect(Collectors.toSet()));
    }

    @Test
    void quickOpenListsEveryViewAndOpensTheChosenOne() throws Exception {
        QuickOpen quick = new QuickOpen(ui.window.context(), ui.window.places());
        List<String> labels = ui.fx(() -> quick.choices().stream().map(QuickOpen.Choice::label).toList());
        for (ViewSpec spec : ui.window.registry().all()) {
            if (!spec.id().equals(ViewRegistry.RAW)) {
                assertTrue(labels.stream().anyMatch(l -> l.startsWith(spec.title() + " — ")), spec.id());
            }
        }
        // a view named by what was typed comes before one whose help text mentions it (the NAO view's
        // help speaks of "parameters": Enter on "Parameters" opened the NAO view)
        List<QuickOpen.Choice> parameters = ui.fx(() -> quick.matching("Parameters"));
        assertEquals("parameters", parameters.get(0).spec().id());
        assertTrue(parameters.stream().anyMatch(c -> c.spec().id().equals("nao")), "the help text still finds it");
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        ui.fxRun(ui.window::quickOpen);
        ui.robot.clickOn("#quick-open-filter");
        ui.robot.write("network");
        ui.robot.type(KeyCode.ENTER);
        ui.await(5, () -> openViews().contains("network"));
        assertNotNull(ui.robot.lookup("#network-table").query());
        // the keyboard moves into the view opened (issue 14: every action by keyboard) ...
        ui.await(5, () -> keyboardIsIn("network"));
        quickOpen("robots");
        ui.await(5, () -> openViews().contains("robots") && keyboardIsIn("robots"));
        // ... and into one already open that Ctrl+K brings to the front
        quickOpen("network");
        ui.await(5, () -> keyboardIsIn("network"));
        assertEquals(2, openViews().size(), "the open network console was chosen, not a second one");
    }

    private void quickOpen(String typed) throws Exception {
        ui.fxRun(ui.window::quickOpen);
        ui.robot.clickOn("#quick-open-filter");
        ui.robot.write(typed);
        ui.robot.type(KeyCode.ENTER);
    }

    /** The window's keyboard focus lies inside the open view {@code id}. */
    private boolean keyboardIsIn(String id) throws Exception {
        return ui.fx(() -> {
            javafx.scene.Node focus = ui.window.scene().getFocusOwner();
            javafx.scene.Node view = ui.window.shell().openViews().stream().filter(v -> v.spec().id().equals(id))
                    .map(v -> v.view().node()).findFirst().orElse(null);
            for (javafx.scene.Node n = focus; n != null && view != null; n = n.getParent()) {
                if (n == view) {
                    return true;
                }
            }
            return false;
        });
    }
}
