package touchline.ui;

import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.store.StoreEnvelopes;
import touchline.ui.views.DebugConsoleView;
import touchline.ui.views.TextView;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The views that follow a log (debug console, text view) show each new line once, newest at
 * the bottom, and a search starts again from what the log holds.
 */
@Tag("ui")
class FollowingViewsUiTest {

    private static final int ROBOT = 51;
    @TempDir
    Path layouts;

    /** A console window with no view open and robot {@link #ROBOT} known. */
    private ConsoleWindowFixture window() throws Exception {
        ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts);
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        ui.console.bus().accept(StoreEnvelopes.status(ui.console.clock().nowMicros(), ROBOT));
        return ui;
    }

    private static void publish(ConsoleWindowFixture ui, String option, String text) {
        ui.console.bus().accept(StoreEnvelopes.text(ui.console.clock().nowMicros(), ROBOT, option, text));
    }

    @Test
    void theDebugConsoleFollowsTheLogOnceAndSearchRereadsIt() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            followAndSearch(ui);
        }
    }

    private static void followAndSearch(ConsoleWindowFixture ui) throws Exception {
        ui.fxRun(() -> ui.window.open("debug-console", ViewSource.NONE));
        DebugConsoleView view = ui.view(DebugConsoleView.class);
        ListView<?> list = ui.fx(() -> ui.robot.from(view.node()).lookup("#debug-lines").queryAs(ListView.class));
        publish(ui, "demo.text", "alpha");
        publish(ui, "demo.text", "beta");
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == 2);
        publish(ui, "demo.text", "gamma");
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == 3);
        long frame = ui.fx(() -> ui.window.pulse().frames());
        ui.await(10, () -> ui.window.pulse().frames() > frame + 5);
        assertEquals(3, (int) ui.fx(() -> list.getItems().size()), "each line once");
        assertTrue(ui.fx(() -> list.getItems().get(2).toString()).endsWith("gamma"), "newest at the bottom");
        ui.fxRun(() -> ui.robot.from(view.node()).lookup("#debug-search").queryAs(TextField.class).setText("beta"));
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == 1);
        assertTrue(ui.fx(() -> list.getItems().get(0).toString()).endsWith("beta"));
    }

    @Test
    void theTextViewShowsOnlyItsOptionsLines() throws Exception {
        try (ConsoleWindowFixture ui = window()) {
            onlyItsOption(ui);
        }
    }

    private static void onlyItsOption(ConsoleWindowFixture ui) throws Exception {
        ui.fxRun(() -> ui.window.open("text", new ViewSource(ROBOT, "mine")));
        TextView view = ui.view(TextView.class);
        publish(ui, "mine", "one");
        publish(ui, "other", "not this");
        publish(ui, "mine", "two");
        ui.await(10, () -> ui.fx(view::shownLines).size() == 2);
        List<String> shown = ui.fx(view::shownLines);
        assertTrue(shown.get(0).endsWith("one") && shown.get(1).endsWith("two"), shown.toString());
    }
}
