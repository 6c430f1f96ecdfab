package touchline.ui.window;

import javafx.geometry.Bounds;
import javafx.scene.Node;
import javafx.scene.control.ButtonBase;
import javafx.scene.control.Label;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.testing.UiTest;
import touchline.ui.window.LayoutNode;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import touchline.ui.frame.FramePulse;
import touchline.ui.frame.ViewSource;
import touchline.ui.referee.GameControllerTabDriver;

/**
 * Every view alone in a 1280×720 window: the menu and the status bar stay whole and in the
 * window, no button is cut to "…", and every table header reads in full.
 */
@UiTest
public class ViewsFitUiTest {

    private ConsoleWindowFixture ui;

    @BeforeEach
    void open() throws Exception {
        ui.laptopSize();
    }

    @AfterEach
    void close() throws Exception {
        ui.console.referee().stop();
        if (field != null) {
            field.close();
        }
    }

    private static final java.util.Set<String> HEADERS_SEEN = new java.util.concurrent.ConcurrentSkipListSet<>();

    private static boolean cut(javafx.scene.control.Labeled l) {
        return l.isVisible() && l.getText() != null && !l.getText().isEmpty() && l.getWidth() + 0.5 < l.prefWidth(-1);
    }

    /** Buttons and field names cut to "…", table headers cut (the HSL referee box checks itself with it too). */
    public static void collect(Node n, String view, List<String> problems) {
        if (n instanceof ButtonBase b && cut(b)) {
            problems.add(view + ": button \"" + b.getText() + "\" cut (" + b.getWidth() + " of " + b.prefWidth(-1) + ")");
        }
        if (n instanceof Label name && name.getText() != null && name.getText().length() <= 12 && cut(name)) {
            problems.add(view + ": field name \"" + name.getText() + "\" cut"); // "Robot", "Source", "RPC" …
        }
        if (n instanceof javafx.scene.control.IndexedCell<?>) {
            return; // rows of data: a cell cut to "…" is the table's business
        }
        if (n instanceof Label t && t.getTooltip() == null && t.getText() != null && t.getText().length() > 12
                && t.getWidth() > 0 && cut(t) && !(t.getParent() != null && t.getParent().getStyleClass().contains("column-header"))) {
            problems.add(view + ": text \"" + t.getText() + "\" cut with no tooltip");
        }
        if (n instanceof Label h && h.getParent() != null && h.getParent().getStyleClass().contains("column-header")) {
            HEADERS_SEEN.add(view + "/" + h.getText());
            if (cut(h)) {
                problems.add(view + ": header \"" + h.getText() + "\" cut");
            }
        }
        if (n instanceof javafx.scene.Parent p) {
            for (Node c : p.getChildrenUnmodifiable()) {
                collect(c, view, problems);
            }
        }
    }

    private java.net.DatagramSocket field;

    private void startGameController() throws Exception {
        field = new java.net.DatagramSocket(new java.net.InetSocketAddress("127.0.0.1", 0));
        new GameControllerTabDriver(ui).start(field);
    }

    @Test
    void everyViewFitsA1280By720Window() throws Exception {
        List<String> problems = new ArrayList<>();
        List<ViewSpec> specs = new ArrayList<>(ui.window.registry().all());
        specs.add(null); // and the demo layout, every pane smaller
        for (ViewSpec one : specs) {
            ViewSpec spec = one != null ? one : new ViewSpec("demo layout", "", "", java.util.Set.of(), null);
            ui.fxRun(() -> ui.window.shell().restore(one != null ? List.of(new LayoutNode.Leaf(0,
                    List.of(new LayoutNode.Entry(one.id(), "")))) : DemoLayout.standard()));
            if (one != null && one.id().equals("gamecontroller")) {
                startGameController(); // its robot rows make it the tallest view
            }
            long start = ui.fx(() -> ui.window.pulse().frames());
            ui.await(30, () -> ui.window.pulse().frames() > start + 35); // past a label check of the frame
            problems.addAll(ui.fx(() -> {
                List<String> out = new ArrayList<>();
                double sceneHeight = ui.window.scene().getHeight();
                Bounds status = ui.window.status().localToScene(ui.window.status().getLayoutBounds());
                if (status.getMaxY() > sceneHeight + 0.5 || status.getHeight() < 10) {
                    out.add(spec.id() + ": status bar out of the window (" + status + ")");
                }
                Node menu = ui.window.scene().getRoot().lookup(".menu-bar");
                Bounds menuBounds = menu.localToScene(menu.getLayoutBounds());
                for (Shell.OpenView v : ui.window.shell().openViews()) {
                    Node frame = v.frame();
                    if (!FramePulse.showing(frame)) {
                        continue;
                    }
                    Bounds viewBounds = frame.localToScene(frame.getLayoutBounds());
                    if (viewBounds.getMinY() < menuBounds.getMaxY() - 0.5 || viewBounds.getMaxY() > status.getMinY() + 0.5) {
                        out.add(spec.id() + ": view " + v.spec().id() + " " + viewBounds + " over the menu or the status bar");
                    }
                    collect(frame, spec.id() + "/" + v.spec().id(), out);
                }
                collect(ui.window.status(), spec.id() + " status bar", out);
                return out;
            }));
        }
        assertEquals(List.of(), problems);
        org.junit.jupiter.api.Assertions.assertTrue(HEADERS_SEEN.containsAll(List.of("robots/robots/Battery", "robots/robots/Online for",
                "network/network/Time", "network/network/Peer")), HEADERS_SEEN.toString());
    }

    /**
     * A view opened from Ctrl+K into the demo layout goes into its narrow left pane: the Viewers
     * and NAO views keep their buttons and field names whole there too (the pane scrolls sideways).
     */
    @Test
    void viewsOpenedIntoTheDemoLayoutsNarrowPaneKeepTheirControlsWhole() throws Exception {
        List<String> problems = new ArrayList<>();
        for (String id : List.of("viewers", "nao")) {
            ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
            long restored = ui.fx(() -> ui.window.pulse().frames());
            ui.await(30, () -> ui.window.pulse().frames() > restored + 5);
            ui.fxRun(() -> ui.window.open(id, ViewSource.NONE));
            ui.await(30, () -> ui.fx(() -> ui.window.shell().openViews().stream()
                    .anyMatch(v -> v.spec().id().equals(id) && FramePulse.showing(v.frame()))));
            long start = ui.fx(() -> ui.window.pulse().frames());
            ui.await(30, () -> ui.window.pulse().frames() > start + 35); // past a label check of the frame
            problems.addAll(ui.fx(() -> {
                List<String> out = new ArrayList<>();
                for (Shell.OpenView v : ui.window.shell().openViews()) {
                    if (v.spec().id().equals(id) && FramePulse.showing(v.frame())) {
                        collect(v.frame(), "demo layout + " + id, out);
                        return out;
                    }
                }
                out.add(id + " not showing after it was opened into the demo layout");
                return out;
            }));
        }
        assertEquals(List.of(), problems);
    }

    /** The replay's file field opened into the demo layout's narrow left pane is wide enough to type a path in. */
    @Test
    void theReplaysFileFieldKeepsItsWidthInTheDemoLayoutsNarrowPane() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
        long restored = ui.fx(() -> ui.window.pulse().frames());
        ui.await(30, () -> ui.window.pulse().frames() > restored + 5);
        ui.fxRun(() -> ui.window.open("replay", ViewSource.NONE));
        ui.await(30, () -> ui.fx(() -> ui.window.scene().getRoot().lookup("#replay-path") != null
                && ui.window.scene().getRoot().lookup("#replay-path").getLayoutBounds().getWidth() > 0));
        long start = ui.fx(() -> ui.window.pulse().frames());
        ui.await(30, () -> ui.window.pulse().frames() > start + 5);
        double width = ui.fx(() -> ui.window.scene().getRoot().lookup("#replay-path").getLayoutBounds().getWidth());
        org.junit.jupiter.api.Assertions.assertTrue(width >= 160, "the replay's file field is " + width + " px wide");
    }

    /**
     * A console viewing another Touchline says so in the status bar's banner, with the server's
     * address: a long one is cut (the whole text in its tooltip) rather than making the window
     * wider than a 1280-pixel screen.
     */
    @Test
    void aLongBannerNeverMakesTheWindowWiderThanA1280Screen() throws Exception {
        int nobody;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            nobody = s.getLocalPort(); // free again once closed: nothing listens there
        }
        ui.console.remote().view(new java.net.URI("ws://127.0.0.1:" + nobody + "/a/rather/long/path/of/the/server"), null);
        ui.await(30, () -> ui.fx(() -> ((Label) ui.window.scene().lookup("#status-silence")).getText().contains("lost")));
        long start = ui.fx(() -> ui.window.pulse().frames());
        ui.await(30, () -> ui.window.pulse().frames() > start + 5);
        double least = ui.fx(() -> ui.window.scene().getRoot().minWidth(-1));
        org.junit.jupiter.api.Assertions.assertTrue(least <= 1280, "the window needs " + least + " px: "
                + ui.fx(() -> ((Label) ui.window.scene().lookup("#status-silence")).getText()));
        Bounds status = ui.fx(() -> ui.window.status().localToScene(ui.window.status().getLayoutBounds()));
        double width = ui.fx(() -> ui.window.scene().getWidth());
        org.junit.jupiter.api.Assertions.assertTrue(status.getMaxX() <= width + 0.5, status + " in " + width);
    }

    /** In the demo layout at 1280 pixels the Robots table shows Game and Authenticity without a sideways scroll. */
    @Test
    void theRobotsTableShowsGameAndAuthenticityInTheDemoLayout() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
        ui.await(30, () -> ui.window.scene().lookup("#robot-table") instanceof javafx.scene.control.TableView<?> t
                && FramePulse.showing(t) && t.getWidth() > 0);
        long start = ui.fx(() -> ui.window.pulse().frames());
        ui.await(30, () -> ui.window.pulse().frames() > start + 5);
        String where = ui.fx(() -> {
            javafx.scene.control.TableView<?> table = (javafx.scene.control.TableView<?>) ui.window.scene().lookup("#robot-table");
            table.applyCss();
            table.layout();
            double right = 0;
            StringBuilder out = new StringBuilder();
            for (javafx.scene.control.TableColumn<?, ?> c : table.getVisibleLeafColumns()) {
                right += c.getWidth();
                if ((c.getText().equals("Game") || c.getText().equals("Authenticity")) && right > table.getWidth() + 0.5) {
                    out.append(c.getText()).append(" ends at ").append(right).append(" of ").append(table.getWidth()).append("; ");
                }
            }
            return out.toString();
        });
        assertEquals("", where);
    }

    /** How much wider than its pane the view's content is (0: it fits, no sideways scroll). */
    private double overflow(String id) throws Exception {
        return ui.fx(() -> {
            Shell.OpenView v = ui.window.shell().openViews().stream().filter(o -> o.spec().id().equals(id)).findFirst()
                    .orElseThrow();
            javafx.scene.Parent root = ui.window.scene().getRoot();
            root.applyCss();
            root.layout();
            Node n = v.view().node();
            while (n != null && !(n instanceof javafx.scene.control.ScrollPane)) {
                n = n.getParent();
            }
            if (!(n instanceof javafx.scene.control.ScrollPane sp) || sp.getContent() == null) {
                return 0.0;
            }
            return Math.max(0, sp.getContent().getLayoutBounds().getWidth() - sp.getViewportBounds().getWidth());
        });
    }

    /**
     * The default (demo) layout at 1280×720 is usable without dragging a divider: the GameController
     * (both teams), the NAO view (Connect) and the Network console opened into it show their
     * controls without a sideways scroll (they get a row of the window's width when no pane is wide enough).
     */
    @Test
    void wideViewsOpenedIntoTheDemoLayoutNeedNoDividerDragged() throws Exception {
        List<String> problems = new ArrayList<>();
        for (String id : List.of("gamecontroller", "nao", "network")) {
            ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
            long restored = ui.fx(() -> ui.window.pulse().frames());
            ui.await(30, () -> ui.window.pulse().frames() > restored + 5);
            if (id.equals("gamecontroller")) {
                field = new java.net.DatagramSocket(new java.net.InetSocketAddress("127.0.0.1", 0));
                new GameControllerTabDriver(ui).start(field, "hsl20"); // opens the tab as the View menu does
                ui.await(30, () -> ui.window.scene().lookup("#gamecontroller-hsl") != null);
            } else {
                ui.fxRun(() -> ui.window.open(id, ViewSource.NONE));
            }
            ui.await(30, () -> ui.fx(() -> ui.window.shell().openViews().stream()
                    .anyMatch(v -> v.spec().id().equals(id) && FramePulse.showing(v.frame()))));
            long start = ui.fx(() -> ui.window.pulse().frames());
            ui.await(30, () -> ui.window.pulse().frames() > start + 10);
            double over = overflow(id);
            if (over > 0.5) {
                problems.add(id + " is " + over + " px wider than its pane");
            }
            if (id.equals("gamecontroller")) {
                ui.console.referee().stop();
                field.close();
                field = null;
            }
        }
        assertEquals(List.of(), problems);
    }

    /**
     * At the PLAYING whistle under openbox at 1280 px the whole window moved 38–75 px sideways for a few
     * seconds: the status bar's texts (the banner "Silent: match mode, …", the meter's "… · debug over
     * limit") asked together for more than the window, and the window laid everything out wider. With
     * the longest texts each shows in play, the window needs no more than 1280 px, the counts, the meter
     * and the frame rate stay whole and the referee's buttons do not move.
     */
    @Test
    void theStatusBarsAndRefereesLongestTextsNeitherWidenTheWindowNorMoveAButton() throws Exception {
        ui.fxRun(() -> ui.window.shell().restore(DemoLayout.standard()));
        field = new java.net.DatagramSocket(new java.net.InetSocketAddress("127.0.0.1", 0));
        new GameControllerTabDriver(ui).start(field, "hsl20");
        ui.await(30, () -> ui.window.scene().lookup("#gamecontroller-hsl") != null);
        long start = ui.fx(() -> ui.window.pulse().frames());
        ui.await(30, () -> ui.window.pulse().frames() > start + 10);
        List<String> buttons = List.of("#gc-ready", "#gc-play", "#gc-stop-resume", "#gc-undo", "#gc-second-half");
        List<String> problems = ui.fx(() -> {
            List<String> out = new ArrayList<>();
            javafx.scene.Parent root = ui.window.scene().getRoot();
            List<Bounds> before = buttons.stream().map(id -> root.lookup(id)).map(b -> b.localToScene(b.getLayoutBounds())).toList();
            // the longest each can show (the pulse refreshes them twice a second: set, laid out and measured at once)
            text(root, "#status-silence", "Silent: match mode, game is PLAYING (GameController at 192.168.100.200:3838)");
            text(root, "#status-rates", "in 12345 pkt/s 123.4 MB/s · out 12345 pkt/s 123.4 MB/s");
            text(root, "#status-malformed", "malformed 1234567");
            text(root, "#status-waiting", "123 requests waiting now");
            text(root, "#status-meter", "team 13: 11999 used · 12000 left · runs out in 12:34 · 12 OVERSIZE · debug over limit");
            text(root, "#status-message", "layout \"a layout with a rather long name for the tournament\" saved");
            text(root, "#status-fps", "60 fps · p99 1234 ms");
            text(root, "#gc-state", "PLAYING · penalty shoot-out · STOPPED · Indirect free kick 13 · 2nd half · robots still see SET");
            root.applyCss();
            root.layout();
            double least = root.minWidth(-1);
            if (least > 1280) {
                out.add("the window needs " + least + " px");
            }
            double width = ui.window.scene().getWidth();
            for (String id : List.of("#status-meter", "#status-fps", "#status-waiting", "#status-malformed")) {
                Label l = (Label) root.lookup(id);
                Bounds b = l.localToScene(l.getLayoutBounds());
                if (l.getWidth() + 0.5 < l.prefWidth(-1) || b.getMaxX() > width + 0.5) {
                    out.add(id + " cut or out of the window: " + b + " of " + l.prefWidth(-1) + " in " + width);
                }
            }
            for (int i = 0; i < buttons.size(); i++) {
                Node b = root.lookup(buttons.get(i));
                Bounds now = b.localToScene(b.getLayoutBounds());
                if (Math.abs(now.getMinX() - before.get(i).getMinX()) > 0.5 || Math.abs(now.getMinY() - before.get(i).getMinY()) > 0.5) {
                    out.add(buttons.get(i) + " moved from " + before.get(i) + " to " + now);
                }
            }
            return out;
        });
        assertEquals(List.of(), problems);
    }

    private static void text(javafx.scene.Parent root, String id, String text) {
        ((Label) java.util.Objects.requireNonNull(root.lookup(id), id)).setText(text);
    }
}
