package touchline.ui;

import javafx.scene.control.ComboBox;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.RobotProcess;
import touchline.ui.layout.LayoutNode;

import java.nio.file.Path;
import java.util.List;

/**
 * Issue 36 item 2: the robot filter of the Debug console, the Network console and Plot fields
 * offers every robot that reports, not only "all robots" (its first read was never due: a
 * "never read" time of Long.MIN_VALUE overflowed the twice-a-second check).
 */
@Tag("ui")
@Tag("integration")
class RobotFiltersUiTest {

    @TempDir
    Path layouts;
    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui = new ConsoleWindowFixture(layouts);
    }

    @AfterEach
    void close() throws Exception {
        ui.close();
    }

    @ParameterizedTest
    @CsvSource({"debug-console, #debug-robot", "network, #network-robot", "field-plot, #field-robot"})
    @SuppressWarnings("unchecked")
    void theFilterOffersTheRobotThatReports(String viewId, String filterId) throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        try (RobotProcess robot = RobotProcess.robot(7, ui.port(), "--rate", "20").start()) {
            ui.fxRun(() -> ui.window.shell().restore(List.of(new LayoutNode.Leaf(0, List.of(new LayoutNode.Entry(viewId, ""))))));
            ui.await(30, () -> ui.console.robots().robots().stream().anyMatch(r -> r.id() == 7));
            ui.await(30, () -> ui.robot.lookup(filterId).queryAs(ComboBox.class).getItems().contains("robot 7"));
            ComboBox<String> filter = ui.fx(() -> ui.robot.lookup(filterId).queryAs(ComboBox.class));
            ui.fxRun(() -> filter.getSelectionModel().select("robot 7"));
            ui.await(30, () -> "robot 7".equals(filter.getValue())); // chosen and kept over the next refreshes
        }
    }
}
