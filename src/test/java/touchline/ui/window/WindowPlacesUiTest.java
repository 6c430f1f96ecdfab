package touchline.ui.window;

import javafx.geometry.Rectangle2D;
import javafx.stage.Screen;
import javafx.stage.Stage;
import javafx.stage.Window;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.UiTest;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The window and the quick-open dialog open where they were closed (headless screen). */
@UiTest
class WindowPlacesUiTest {

    @TempDir
    Path layouts;

    private static WindowPlace placeOf(Window w) {
        return new WindowPlace(w.getX(), w.getY(), w.getWidth(), w.getHeight(), false);
    }

    @Test
    void theWindowFillsTheScreenUpTo1400By900FirstAndOpensWhereItWasClosedNext() throws Exception {
        ConsoleWindowFixture first = new ConsoleWindowFixture(layouts);
        Rectangle2D screen = first.fx(() -> Screen.getPrimary().getVisualBounds());
        WindowPlace expected = WindowPlace.centred(screen, WindowPlaces.FIRST_START_FRACTION, 1400, 900);
        assertEquals(expected, first.fx(() -> placeOf(first.window.scene().getWindow())));
        assertTrue(expected.width() > 200 && expected.height() > 200, expected.toString());
        WindowPlace moved = new WindowPlace(screen.getMinX() + 40, screen.getMinY() + 30,
                Math.round(screen.getWidth() * 0.6), Math.round(screen.getHeight() * 0.5), false);
        first.fxRun(() -> {
            Window w = first.window.scene().getWindow();
            w.setX(moved.x());
            w.setY(moved.y());
            w.setWidth(moved.width());
            w.setHeight(moved.height());
        });
        first.close();
        assertTrue(Files.isRegularFile(layouts.resolve("windows.properties")));

        ConsoleWindowFixture second = new ConsoleWindowFixture(layouts);
        try {
            assertEquals(moved, second.fx(() -> placeOf(second.window.scene().getWindow())));
        } finally {
            second.close();
        }
    }

    @Test
    void quickOpenRemembersItsPlace() throws Exception {
        ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts);
        try {
            ui.fxRun(ui.window::quickOpen);
            Stage quick = ui.fx(() -> (Stage) Window.getWindows().stream()
                    .filter(w -> w instanceof Stage s && "Open view".equals(s.getTitle())).findFirst().orElseThrow());
            WindowPlace first = ui.fx(() -> placeOf(quick));
            assertTrue(first.width() >= 600 && first.height() >= 380, first.toString());
            WindowPlace moved = new WindowPlace(first.x() + 25, first.y() + 15, 700, 450, false);
            ui.fxRun(() -> {
                quick.setX(moved.x());
                quick.setY(moved.y());
                quick.setWidth(moved.width());
                quick.setHeight(moved.height());
                quick.close();
            });
            ui.fxRun(ui.window::quickOpen);
            Stage again = ui.fx(() -> (Stage) Window.getWindows().stream()
                    .filter(w -> w instanceof Stage s && "Open view".equals(s.getTitle()) && s.isShowing())
                    .findFirst().orElseThrow());
            assertEquals(moved, ui.fx(() -> placeOf(again)));
            ui.fxRun(again::close);
        } finally {
            ui.close();
        }
    }

    @Test
    void aPlaceOnAScreenThatIsGoneIsNotUsed() {
        List<Rectangle2D> screens = List.of(new Rectangle2D(0, 0, 1280, 720));
        assertTrue(new WindowPlace(100, 50, 800, 600, false).reachableOn(screens));
        assertTrue(new WindowPlace(-600, 10, 800, 600, false).reachableOn(screens), "partly off the left edge");
        assertFalse(new WindowPlace(1900, 50, 800, 600, false).reachableOn(screens), "on a second screen unplugged since");
        assertFalse(new WindowPlace(100, -600, 800, 600, false).reachableOn(screens), "title bar above the screen");
        assertFalse(new WindowPlace(100, 50, 0, 0, false).reachableOn(screens));
        assertEquals(new WindowPlace(1280 * 0.05, 36, 1152, 648, false),
                WindowPlace.centred(new Rectangle2D(0, 0, 1280, 720), 0.9, 1400, 900));
        assertEquals(new WindowPlace(260, 90, 1400, 900, false),
                WindowPlace.centred(new Rectangle2D(0, 0, 1920, 1080), 0.9, 1400, 900));
    }
}
