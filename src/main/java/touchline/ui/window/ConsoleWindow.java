package touchline.ui.window;

import atlantafx.base.theme.PrimerDark;
import atlantafx.base.theme.PrimerLight;
import javafx.application.Application;
import javafx.scene.Scene;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.MenuItem;
import javafx.scene.control.SeparatorMenuItem;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyCodeCombination;
import javafx.scene.input.KeyCombination;
import javafx.scene.layout.BorderPane;
import javafx.stage.Stage;
import touchline.app.Console;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;

import java.io.IOException;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import touchline.ui.frame.ConsoleChanges;
import touchline.ui.frame.FramePulse;
import touchline.ui.frame.ViewSource;
import touchline.ui.viewers.ServeToggle;

/**
 * The console's one window: menus (layouts, views, theme, help), the docking shell, the status
 * bar, Ctrl+K quick-open, and the frame pulse that drives every view. Built on the FX thread
 * from an already started {@link Console}; closing the window does not close the Console.
 */
public final class ConsoleWindow {

    private final UiSettings settings;
    private final ViewRegistry registry = new ViewRegistry();
    private final Shell shell;
    private final ViewContext context;
    private final StatusBar status;
    private final FramePulse pulse;
    private final LayoutStore layouts;
    private final WindowPlaces places;
    private final BorderPane root = new BorderPane();
    private final Set<String> demoSwitched = new HashSet<>();
    private final ServeToggle serving;
    private final LayoutMenu layoutMenu;
    private final HelpMenu helpMenu;
    private Shortcuts shortcuts;
    private Stage stage;
    private boolean dark;

    /** Composes the window over {@code console}'s services; the views get them, never the console. */
    public ConsoleWindow(Console console, UiSettings settings) {
        this.settings = settings;
        this.layouts = new LayoutStore(settings.layoutDir());
        this.places = settings.windowPlaces();
        this.dark = settings.dark();
        // the wanted debug options belong to the user: kept beside the layouts, wanted again now
        console.optionSwitches().rememberWanted(settings.layoutDir().resolve("wanted-options.properties"));
        Shell[] holder = new Shell[1];
        this.serving = new ServeToggle(console.serving());
        this.context = new ViewContext(console.field(), console.optionSwitches(), console.referee(), console.naos(),
                console.recordings(), console.replays(), console.teamSchemas(), console.teamBudget(), console.remote(),
                console.bridges(), registry, (spec, src) -> holder[0].open(spec, src), settings.layoutDir(), serving);
        this.shell = new Shell(registry, spec -> src -> spec.factory().apply(context, src));
        holder[0] = shell;
        this.status = new StatusBar(context.status(), context.field(), context.budget());
        this.pulse = new FramePulse(shell::pulled, status, context.field().clock(), this::demoStep,
                new ConsoleChanges(context.field(), context.referee().matchMode(), context.status(), serving::server)::read,
                settings.frameCap());
        shell.onChange(pulse::input);
        this.layoutMenu = new LayoutMenu(layouts, shell, status, places, () -> this.stage);
        this.helpMenu = new HelpMenu(shell, context, places, () -> this.stage, () -> shortcuts);
        MenuBar bar = menus();
        shortcuts = new Shortcuts(bar);
        root.setTop(bar);
        root.setCenter(shell.node());
        root.setBottom(status);
    }

    /** How long closing the window waits for the recording's file to be finished (a stuck disk must not hang it). */
    static final long FINISH_RECORDING_MILLIS = 20_000;

    /** Shows the window on {@code stage} with the demo layout, the "last" layout or the default. */
    public ConsoleWindow show(Stage stage) {
        return show(stage, false);
    }

    /**
     * Shows the window; with {@code viewsAfterShown} the window opens with its menus and status bar
     * first and the layout's views are built in the next turn of the JavaFX thread, so the window
     * is on screen a second or more sooner (the console's start, docs/archive/benchmarks-sessions.md "Start").
     */
    public ConsoleWindow show(Stage stage, boolean viewsAfterShown) {
        this.stage = stage;
        applyTheme();
        Scene scene = new Scene(root);
        scene.getStylesheets().add(ConsoleWindow.class.getResource("touchline.css").toExternalForm());
        scene.getStylesheets().add(ConsoleWindow.class.getResource("bento-themed.css").toExternalForm());
        scene.getAccelerators().put(new KeyCodeCombination(KeyCode.K, KeyCombination.SHORTCUT_DOWN), this::quickOpen);
        stage.setScene(scene);
        // any of the console's windows touched: the idle pulse wakes up; F1 gives help in every window
        EveryWindow<javafx.scene.input.InputEvent> input = new EveryWindow<>(javafx.scene.input.InputEvent.ANY,
                (e, w) -> pulse.input());
        EveryWindow<javafx.scene.input.KeyEvent> f1 = new EveryWindow<>(javafx.scene.input.KeyEvent.KEY_PRESSED,
                helpMenu::key);
        places.keep(stage, "main", 1400, 900);
        stage.setTitle(context.remote().status().map(r -> context.field().runtime().version().title() + " — viewing " + r.url())
                .orElse(context.field().runtime().version().title() + " — UDP port " + context.field().port()));
        Optional<List<LayoutNode>> last = settings.demo() ? Optional.empty() : layoutMenu.loadQuietly("last");
        boolean[] restored = new boolean[1];
        Runnable restore = () -> {
            if (stage.isShowing() || !viewsAfterShown) {
                shell.restore(last.orElseGet(DemoLayout::standard));
                restored[0] = true;
            }
        };
        if (!viewsAfterShown) {
            restore.run();
        }
        RecordingOnClose recording = new RecordingOnClose(context.recordings(), status::say, FINISH_RECORDING_MILLIS);
        stage.setOnCloseRequest(e -> recording.request(e, stage));
        stage.setOnHiding(e -> {
            if (restored[0]) { // closed before its views were built: the saved "last" layout stays as it was
                layoutMenu.saveQuietly("last");
            }
            pulse.close();
            input.close();
            f1.close();
            serving.close();
            recording.hiding(); // the recording is finished off the FX thread, however the window was closed
        });
        // light on the laptop: a minimised window does no frame work; a touched one wakes up
        stage.iconifiedProperty().addListener((o, was, minimised) -> pulse.iconified(minimised));
        stage.show();
        pulse.start();
        if (viewsAfterShown) {
            // after the first frame: the pulse that draws it, then the views
            new javafx.animation.AnimationTimer() {
                @Override
                public void handle(long now) {
                    stop();
                    javafx.application.Platform.runLater(restore);
                }
            }.start();
        }
        return this;
    }

    /**
     * Hides the window (which ends {@code touchline console}) after {@code frames} pulses: the way out
     * of the class-data-sharing training run, which must end normally for the JVM to write its archive.
     */
    public void closeAfterFrames(int frames) {
        new javafx.animation.AnimationTimer() {
            private int seen;

            @Override
            public void handle(long now) {
                if (++seen >= frames) {
                    stop();
                    stage.hide();
                }
            }
        }.start();
    }

    public Shell shell() { return shell; }
    public FramePulse pulse() { return pulse; }
    public StatusBar status() { return status; }
    public LayoutStore layouts() { return layouts; }
    public WindowPlaces places() { return places; }
    public ViewRegistry registry() { return registry; }
    public ViewContext context() { return context; }
    public ServeToggle serving() { return serving; }
    public Scene scene() { return root.getScene(); }

    public ConsoleWindow open(String viewId, ViewSource source) {
        registry.byId(viewId).ifPresent(spec -> shell.open(spec, source));
        return this;
    }

    public void saveLayout(String name) throws IOException {
        layoutMenu.save(name);
    }

    /** Renames a saved layout; the status line says what happened or why not. */
    public void renameLayout(String from, String to) {
        layoutMenu.rename(from, to);
    }

    /** Deletes a saved layout; the status line says so. */
    public void deleteLayout(String name) {
        layoutMenu.delete(name);
    }

    public boolean loadLayout(String name) throws IOException {
        return layoutMenu.load(name);
    }

    public void setDark(boolean dark) {
        this.dark = dark;
        applyTheme();
    }

    private void applyTheme() {
        String css = dark ? new PrimerDark().getUserAgentStylesheet() : new PrimerLight().getUserAgentStylesheet();
        // the theme names a class-path resource; resolve it to a URL so any class loader finds it
        java.net.URL url = ConsoleWindow.class.getResource(css);
        Application.setUserAgentStylesheet(url != null ? url.toExternalForm() : css);
    }

    /** F1: the help of the view that has the keyboard (every view's when none has). */
    public Stage helpForFocusedView() {
        return helpMenu.forFocusedView();
    }

    /** Help → Keyboard shortcuts (Ctrl+/): the sheet, read from the menus' accelerators. */
    public Stage shortcutSheet() {
        return helpMenu.shortcutSheet();
    }

    public void quickOpen() {
        new QuickOpen(context, places, shell::openAndFocus).show(stage);
    }

    /** In demo mode: switch the demo options on, and choose the demo's match items, for every robot once its list arrived. */
    private void demoStep() {
        if (!settings.demo() || pulse.frames() % 15 != 0) {
            return;
        }
        for (RobotSnapshot r : context.field().robots().robots()) {
            for (OptionState o : context.field().options().options(r.id()).options()) {
                if (DemoLayout.DEMO_OPTIONS.contains(o.name()) && demoSwitched.add(r.id() + "/" + o.name())) {
                    context.switches().set(r.id(), o.name(), true);
                }
            }
            if (context.field().options().options(r.id()).listReceived() && demoSwitched.add(r.id() + "/in the game")) {
                context.switches().options().setMatchItems(r.id(), DemoLayout.MATCH_ITEMS);
            }
        }
    }

    private MenuBar menus() {
        Menu views = new Menu("_View");
        for (ViewSpec s : registry.all()) {
            if (s.id().equals(ViewRegistry.RAW)) {
                continue;
            }
            MenuItem item = new MenuItem(s.title());
            item.setOnAction(e -> shell.openAndFocus(s, ViewSource.NONE));
            views.getItems().add(item);
        }
        MenuItem quick = new MenuItem("_Quick open…");
        quick.setAccelerator(new KeyCodeCombination(KeyCode.K, KeyCombination.SHORTCUT_DOWN));
        quick.setOnAction(e -> quickOpen());
        javafx.scene.control.CheckMenuItem serve = new javafx.scene.control.CheckMenuItem("Serve to viewers");
        serve.setId("menu-serve");
        serve.setAccelerator(new KeyCodeCombination(KeyCode.V, KeyCombination.SHORTCUT_DOWN, KeyCombination.SHIFT_DOWN));
        serve.setOnAction(e -> {
            status.say(serving.toggle());
            serve.setSelected(serving.serving());
        });
        views.setOnShowing(e -> serve.setSelected(serving.serving()));
        views.getItems().addAll(new SeparatorMenuItem(), quick, serve);

        Menu theme = new Menu("_Theme");
        MenuItem darkItem = new MenuItem("_Dark");
        darkItem.setOnAction(e -> setDark(true));
        MenuItem lightItem = new MenuItem("_Light");
        lightItem.setOnAction(e -> setDark(false));
        theme.getItems().addAll(darkItem, lightItem);

        return new MenuBar(layoutMenu.menu(), views, theme, helpMenu.menu());
    }
}
