package touchline.ui.consoles;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.SelectionMode;
import javafx.scene.control.TextField;
import javafx.scene.control.ToggleButton;
import javafx.scene.input.Clipboard;
import javafx.scene.input.ClipboardContent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.FlowPane;
import touchline.model.store.SequencedRing;
import touchline.model.store.TextLine;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;
import touchline.ui.frame.RobotFilter;
import touchline.ui.render.SkinPart;

/**
 * Time-stamped text from the robots: filter by robot, search, pause, copy. It holds the newest
 * {@link #SHOWN} lines (up to a tenth more before the oldest go); the text
 * log behind it is capped too, so a chatty robot cannot grow memory. While it follows the
 * newest line its list holds only the last few hundred ({@link LogList}); a selection or a pause
 * makes every line scrollable.
 */
public final class DebugConsoleView implements View {

    static final int SHOWN = 5_000;
    static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS").withZone(ZoneId.systemDefault());

    private final ViewContext context;
    private final ListView<String> lines = new ListView<>();
    private final RobotFilter robot;
    private final TextField search = new TextField();
    private final ToggleButton pause = new ToggleButton("Pause");
    private final Label count = new Label();
    private final touchline.ui.frame.PacedText countText = new touchline.ui.frame.PacedText();
    /** What Copy did, shown for a few seconds ({@link #FEEDBACK_FRAMES}). */
    private final Label feedback = new Label();
    static final int FEEDBACK_FRAMES = 240;
    private long feedbackUntilFrame;
    private long frameNow;
    /** What arrived while paused counts from the store's version at the pause. */
    private long pausedAtVersion = -1;
    private final BorderPane root = new BorderPane();
    private final LogList<TextLine, String> log = new LogList<>(lines, SHOWN);
    /** The newest lines while nobody uses the list (it stands still meanwhile, see {@link #useTheList}). */
    private final NewestLines newest = new NewestLines(ROW_HEIGHT, ROW_INDENT, this::scrollBarThickness);
    static final double ROW_HEIGHT = 22;
    /** Where a row's text starts: the list's border and its row's padding (AtlantaFX). */
    static final double ROW_INDENT = 8;
    private double scrollBarThickness;
    private final SkinPart<javafx.scene.control.ScrollBar> upright = new SkinPart<>(lines, ".scroll-bar",
            javafx.scene.control.ScrollBar.class, b -> b.getOrientation() == javafx.geometry.Orientation.VERTICAL);

    public DebugConsoleView(ViewContext context) {
        this.context = context;
        this.robot = new RobotFilter(context.field());
        lines.setId("debug-lines");
        robot.setId("debug-robot");
        lines.getSelectionModel().setSelectionMode(SelectionMode.MULTIPLE);
        lines.setStyle("-fx-font-family: monospace;");
        lines.setFixedCellSize(ROW_HEIGHT); // no per-cell measuring: appending stays cheap
        newest.setId("debug-newest");
        newest.setStyle("-fx-font-family: monospace;");
        // the list comes up as soon as the pointer or the keyboard reaches it, before it acts on a click or a key
        lines.hoverProperty().addListener((o, a, b) -> useTheList(someoneAtTheList()));
        lines.focusedProperty().addListener((o, a, b) -> useTheList(someoneAtTheList()));
        search.setPromptText("search (Ctrl+F)");
        search.setId("debug-search");
        count.setId("debug-count");
        feedback.setId("debug-feedback");
        pause.setId("debug-pause");
        lines.setCellFactory(l -> new SearchHitCell(() -> search.getText()));
        root.addEventFilter(javafx.scene.input.KeyEvent.KEY_PRESSED, e -> {
            if (e.isShortcutDown() && e.getCode() == javafx.scene.input.KeyCode.F) {
                search.requestFocus();
                search.selectAll();
                e.consume();
            } else if (e.isShortcutDown() && e.getCode() == javafx.scene.input.KeyCode.C && lines.isFocused()) {
                copy();
                e.consume();
            }
        });
        robot.valueProperty().addListener((o, a, b) -> log.reload());
        search.textProperty().addListener((o, a, b) -> log.reload());
        pause.selectedProperty().addListener((o, a, b) -> {
            pausedAtVersion = b ? context.stores().text().version() : -1;
            if (!b) {
                log.reload();
            }
        });
        Button copy = new Button("Copy");
        copy.setId("debug-copy");
        copy.setOnAction(e -> copy());
        Button clear = new Button("Clear");
        clear.setOnAction(e -> log.clear());
        for (javafx.scene.control.Control c : List.of(pause, copy, clear, robot)) {
            c.setMinWidth(javafx.scene.layout.Region.USE_PREF_SIZE);
        }
        search.setPrefColumnCount(10);
        FlowPane bar = new FlowPane(8, 4, new Label("Robot"), robot, search, pause, copy, clear, count, feedback); // wraps when narrow
        bar.setStyle("-fx-padding: 4 8 4 8; -fx-alignment: center-left;");
        root.setTop(bar);
        root.setCenter(new javafx.scene.layout.StackPane(newest, lines));
        useTheList(false);
    }

    /**
     * Whether the list shows and follows the log, or the plain newest lines do in its place ({@link
     * NewestLines}): following a log in the list costs the window a fifth of its time with the demo team
     * (docs/archive/benchmarks-sessions.md, "Eighteenth session"), and at a tournament the console mostly follows with
     * nobody at it. The list comes up, at the newest line, as soon as the user points at it, tabs to it,
     * selects, pauses or searches; it goes again when none of these holds. Both look the same.
     */
    private void useTheList(boolean list) {
        log.glance(list ? null : newest);
        newest.setVisible(!list);
        lines.setOpacity(list ? 1 : 0); // not drawn, still there for the pointer and the keyboard
    }

    /**
     * How thick the list's scroll bars are (0 until its skin has them). A bar the list does not need
     * is hidden and so not styled yet: it is styled here, once.
     */
    private double scrollBarThickness() {
        if (scrollBarThickness == 0 && upright.get() != null) {
            javafx.scene.control.ScrollBar bar = upright.get();
            if (bar.getSkin() == null) {
                bar.applyCss();
            }
            scrollBarThickness = bar.prefWidth(-1);
        }
        return scrollBarThickness;
    }

    /** The user points at the list, has focused it, selected a line, paused or searches. */
    private boolean someoneAtTheList() {
        return lines.isHover() || lines.isFocused() || !lines.getSelectionModel().isEmpty() || pause.isSelected()
                || search.getText() != null && !search.getText().isEmpty();
    }

    private void copy() {
        List<String> chosen = lines.getSelectionModel().getSelectedItems();
        List<String> text = chosen.isEmpty() ? log.all() : chosen;
        ClipboardContent c = new ClipboardContent();
        c.putString(String.join("\n", text));
        Clipboard.getSystemClipboard().setContent(c);
        feedback.setText("copied " + text.size() + (text.size() == 1 ? " line" : " lines")
                + (chosen.isEmpty() ? " (all shown)" : " (selected)"));
        feedbackUntilFrame = frameNow + FEEDBACK_FRAMES;
    }

    static String format(TextLine l) {
        return TIME.format(Instant.ofEpochSecond(0, l.timeMicros() * 1000)) + "  [" + l.robotId() + "] "
                + l.option() + ": " + l.text();
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        robot.refresh();
        frameNow = frame.frame();
        showCount(countText.due(frame.nowMicros()));
        if (frameNow > feedbackUntilFrame && !feedback.getText().isEmpty()) {
            feedback.setText("");
        }
        useTheList(someoneAtTheList());
        if (pause.isSelected()) {
            log.holdEverything(); // every line scrollable while paused
            // every line the log took since the pause, whatever the filters (they apply on resume)
            long waiting = Math.max(0, context.stores().text().version() - pausedAtVersion);
            showCount(countText.offer("paused — " + waiting + " new", frame.nowMicros()));
            return;
        }
        String needle = search.getText() == null ? "" : search.getText().toLowerCase(Locale.ROOT);
        int robotId = robot.robotId();
        SequencedRing.Entry<TextLine> newest = log.follow(lines.getSelectionModel().isEmpty(), context.stores().text().version(),
                (after, max) -> context.stores().text().since(after, robotId, max), l -> {
                    String s = format(l);
                    return needle.isEmpty() || s.toLowerCase(Locale.ROOT).contains(needle) ? s : null;
                });
        if (newest == null) {
            return;
        }
        frame.shown(newest.value().timeMicros());
        showCount(countText.offer(log.all().size() + " lines", frame.nowMicros()));
    }

    private void showCount(String text) {
        if (text != null) {
            count.setText(text);
        }
    }
}
