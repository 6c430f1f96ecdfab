package touchline.ui;

import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
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
    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui = new ConsoleWindowFixture(layouts);
        ui.fxRun(() -> ui.window.shell().restore(List.of()));
        ui.console.bus().accept(StoreEnvelopes.status(now(), ROBOT));
    }

    @AfterEach
    void close() throws Exception {
        ui.close();
    }

    private long now() {
        return ui.console.clock().nowMicros();
    }

    @Test
    void theDebugConsoleFollowsTheLogOnceAndSearchRereadsIt() throws Exception {
        ui.fxRun(() -> ui.window.open("debug-console", ViewSource.NONE));
        DebugConsoleView view = ui.view(DebugConsoleView.class);
        ListView<?> list = ui.fx(() -> ui.robot.from(view.node()).lookup("#debug-lines").queryAs(ListView.class));
        ui.console.bus().accept(StoreEnvelopes.text(now(), ROBOT, "demo.text", "alpha"));
        ui.console.bus().accept(StoreEnvelopes.text(now(), ROBOT, "demo.text", "beta"));
        ui.await(10, () -> ui.fx(() -> list.getItems().size()) == 2);
        ui.console.bus().accept(StoreEnvelopes.text(now(), ROBOT, "demo.text", "gamma"));
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
        ui.fxRun(() -> ui.window.open("text", new ViewSource(ROBOT, "mine")));
        TextView view = ui.view(TextView.class);
        ui.console.bus().accept(StoreEnvelopes.text(now(), ROBOT, "mine", "one"));
        ui.console.bus().accept(StoreEnvelopes.text(now(), ROBOT, "other", "not this"));
        ui.console.bus().accept(StoreEnvelopes.text(now(), ROBOT, "mine", "two"));
        ui.await(10, () -> ui.fx(view::shownLines).size() == 2);
        List<String> shown = ui.fx(view::shownLines);
        assertTrue(shown.get(0).endsWith("one") && shown.get(1).endsWith("two"), shown.toString());
    }
}
