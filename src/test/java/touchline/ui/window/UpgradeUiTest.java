package touchline.ui.window;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.ProductVersion;
import touchline.testing.UiTest;
import touchline.ui.window.LayoutCodec;
import touchline.ui.window.LayoutNode;
import touchline.ui.window.LayoutStore;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * An upgrade keeps the user's configuration: the layout directory the previous version (0.1.0)
 * wrote — committed as a fixture in src/test/resources/layouts/0.1.0, copied unchanged — opens
 * in this version with every view, its source (robot and option), the window arrangement and
 * the window's place, and the configuration directory stays where 0.1.0 kept it. The window
 * names this version in its title and says the transport and priority in use.
 */
@UiTest
class UpgradeUiTest {

    private static final Path PREVIOUS = Path.of("src/test/resources/layouts/0.1.0");

    @TempDir
    Path home;

    @Test
    void thePreviousVersionsLayoutsAndWindowPlaceOpenUnchanged() throws Exception {
        Path layouts = home.resolve("layouts");
        Files.createDirectories(layouts);
        try (var files = Files.list(PREVIOUS)) {
            for (Path f : files.toList()) {
                Files.copy(f, layouts.resolve(f.getFileName()));
            }
        }
        List<LayoutNode> previous = new LayoutCodec().read(
                Files.readString(PREVIOUS.resolve("match day.layout"), StandardCharsets.UTF_8));
        assertEquals(List.of("robots", "options", "regions 2/havimo.region", "plot 3/demo.plotter", "debug-console",
                "network", "field"), views(previous), "the fixture is read whole");

        ConsoleWindowFixture ui = new ConsoleWindowFixture(layouts);
        try {
            // at start the window opens the "last" layout the previous version saved on closing
            assertEquals(views(previous), ui.fx(() -> views(ui.window.shell().capture())));
            assertEquals(new WindowPlace(40, 30, 1100, 700, false), ui.fx(() -> {
                javafx.stage.Window w = ui.window.scene().getWindow();
                return new WindowPlace(w.getX(), w.getY(), w.getWidth(), w.getHeight(), false);
            }), "the main window where 0.1.0 left it");

            assertEquals(List.of("last", "match day"), ui.window.layouts().names());
            ui.fxRun(() -> ui.window.shell().restore(touchline.ui.window.DemoLayout.standard()));
            assertTrue(ui.fx(() -> ui.window.loadLayout("match day")), "the named layout opens from the menu's store");
            assertEquals(views(previous), ui.fx(() -> views(ui.window.shell().capture())));

            String title = ui.fx(() -> ((javafx.stage.Stage) ui.window.scene().getWindow()).getTitle());
            assertTrue(title.startsWith(ProductVersion.ofThisBuild().title() + " — UDP port "), title);
            javafx.scene.control.Label platform = ui.fx(() ->
                    (javafx.scene.control.Label) ui.window.scene().lookup("#status-platform"));
            assertEquals(ui.console.field().runtime().portability(), ui.fx(platform::getText));

            // Help → About Touchline… says the version, the transport and the sender's priority
            ui.fxRun(() -> ((javafx.scene.control.MenuBar) ((javafx.scene.layout.BorderPane) ui.window.scene().getRoot())
                    .getTop()).getMenus().stream().flatMap(m -> m.getItems().stream())
                    .filter(i -> "help-about".equals(i.getId())).findFirst().orElseThrow().fire());
            ui.await(10, () -> javafx.stage.Window.getWindows().stream()
                    .anyMatch(w -> w.getScene() != null && w.getScene().lookup("#help-about-text") != null));
            String about = ui.fx(() -> javafx.stage.Window.getWindows().stream()
                    .map(w -> w.getScene() == null ? null : w.getScene().lookup("#help-about-text"))
                    .filter(java.util.Objects::nonNull).map(n -> ((javafx.scene.control.Label) n).getText())
                    .findFirst().orElseThrow());
            assertTrue(about.contains("UDP transport: " + ui.console.field().transportDescription()), about);
            assertTrue(about.contains("GameController sender: " + ui.console.field().runtime().priority()), about);
        } finally {
            ui.close();
        }
    }

    @Test
    void theConfigurationDirectoryIsWherePreviousVersionsKeptIt() {
        // moving it would lose every user's layouts on upgrade: ~/.config/touchline/layouts since 0.1.0
        assertEquals(Path.of(System.getProperty("user.home"), ".config", "touchline", "layouts"),
                LayoutStore.defaultDir());
    }

    /** Every view of every window in order, with its source when it has one: "plot 3/demo.plotter". */
    private static List<String> views(List<LayoutNode> windows) {
        List<String> out = new ArrayList<>();
        for (LayoutNode w : windows) {
            collect(w, out);
        }
        return out;
    }

    private static void collect(LayoutNode node, List<String> out) {
        if (node instanceof LayoutNode.Leaf leaf) {
            leaf.views().forEach(e -> out.add(e.source().isEmpty() ? e.viewId() : e.viewId() + " " + e.source()));
        } else if (node instanceof LayoutNode.Branch branch) {
            branch.children().forEach(c -> collect(c, out));
        }
    }
}
