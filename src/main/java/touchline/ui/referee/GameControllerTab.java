package touchline.ui.referee;

import javafx.geometry.Insets;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.CheckBox;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.TextField;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.FlowPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import touchline.app.LiveField;
import touchline.app.game.EmbeddedGameController;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ViewContext;

/**
 * The GameController tab: set up a practice game (format, teams, for HSL the competition and
 * colours, where to send; remembered for the next start), start the console's embedded
 * GameController and referee it with {@link HslRefereeView} (HSL 2026, the default) or
 * {@link GameControllerView} (the older formats); and, always, match mode's state with its
 * explicit, logged override switch. What is decided is {@link GameControllerTabModel}'s; the tab
 * binds its controls to it.
 */
public final class GameControllerTab implements View {

    private final GameControllerTabModel model;
    private final LiveField field;
    private final BorderPane root = new BorderPane();
    private final ComboBox<String> format = new ComboBox<>();
    private final TextField teamA = new TextField();
    private final TextField teamB = new TextField();
    private final TextField destinations = new TextField();
    private final TextField returnPort = new TextField();
    private final CheckBox realtime = new CheckBox("Real-time priority for the sender");
    private final HslSetup hsl = new HslSetup();
    private final Label setupMessage = new Label();
    private final Label priority = new Label();
    private final Label monitors = new Label();
    private final Label matchNotice = new Label();
    private final javafx.scene.control.Tooltip matchNoticeTip = new javafx.scene.control.Tooltip();
    private final CheckBox override = new CheckBox("Override match mode (logged)");
    private final TextField overrideReason = new TextField();
    private final VBox setup;
    private View referee;

    public GameControllerTab(ViewContext context, ViewSource source) {
        this.model = new GameControllerTabModel(context.referee(), context.status()::waitingNow, context.settingsDir());
        this.field = context.field();
        root.setId("gamecontroller-tab");
        format.getItems().addAll(GameSetup.FORMATS);
        format.valueProperty().addListener((o, was, now) -> hsl.showFor(GameSetup.profile(now)));
        format.setId("gc-format");
        teamA.setId("gc-team-a");
        teamB.setId("gc-team-b");
        destinations.setId("gc-dest");
        destinations.setPrefColumnCount(36);
        returnPort.setPromptText("default");
        returnPort.setPrefColumnCount(6);
        teamA.setPrefColumnCount(4);
        teamB.setPrefColumnCount(4);
        Button start = new Button("Start GameController");
        start.setId("gc-start");
        setupMessage.setId("gc-setup-message");
        start.setDefaultButton(true);
        start.setOnAction(e -> start());
        // on by default (Linux, root or CAP_SYS_NICE; where it is not granted the running tab says why)
        realtime.setId("gc-realtime");
        priority.setId("gc-priority");
        monitors.setId("gc-monitors");
        setup = new VBox(8,
                new FlowPane(8, 8, new Label("Format"), format, new Label("Team A (left, kicks off)"), teamA,
                        new Label("Team B"), teamB),
                hsl.node(),
                new FlowPane(8, 8, new Label("Send to (host:port, comma separated)"), destinations,
                        new Label("Return port"), returnPort),
                realtime, start, setupMessage);
        setup.setPadding(new Insets(8));
        overrideReason.setPromptText("reason (required to override)");
        override.setId("gc-override");
        override.setOnAction(e -> toggleOverride());
        matchNotice.setId("match-notice");
        // one line that takes the room left and never asks for more: a longer notice (READY's, a
        // hint) must not widen the tab, or the frame scrolls and every referee button moves; the
        // whole text is in the tooltip
        matchNotice.setMinWidth(0);
        matchNotice.setPrefWidth(0);
        matchNotice.setMaxWidth(Double.MAX_VALUE);
        matchNotice.setTooltip(matchNoticeTip);
        override.setMinWidth(javafx.scene.layout.Region.USE_PREF_SIZE);
        overrideReason.setPrefColumnCount(16);
        HBox overriding = new HBox(8, override, overrideReason);
        overriding.setAlignment(javafx.geometry.Pos.CENTER_LEFT);
        // two lines of fixed height: the notice on its own (the whole width), the override below
        VBox bottom = new VBox(4, matchNotice, overriding);
        bottom.setPadding(new Insets(4, 8, 4, 8));
        root.setCenter(setup);
        root.setBottom(bottom);
        fill(model.initialSetup());
        hsl.showFor(GameSetup.profile(format.getValue()));
    }

    private void fill(GameSetup setup) {
        format.setValue(setup.format());
        teamA.setText(setup.teamA());
        teamB.setText(setup.teamB());
        destinations.setText(setup.destinations());
        returnPort.setText(setup.returnPort());
        realtime.setSelected(setup.realtime());
        hsl.fill(setup);
    }

    /** What the form says now. */
    private GameSetup form() {
        return new GameSetup(format.getValue(), teamA.getText(), teamB.getText(), destinations.getText(),
                returnPort.getText(), realtime.isSelected(), hsl.competition(), hsl.fieldA(), hsl.keeperA(),
                hsl.fieldB(), hsl.keeperB(), hsl.monitorPort());
    }

    private void start() {
        setupMessage.setText(model.start(form()));
    }

    /** Shows the referee controls of a running GameController (started here or elsewhere). */
    private void show(EmbeddedGameController gc) {
        referee = gc.hsl() ? new HslRefereeView(new HslRefereeModel(gc.runtime()), gc, field)
                : new GameControllerView(gc.runtime(), gc);
        Button stop = new Button("Stop GameController");
        stop.setId("gc-stop");
        stop.setOnAction(e -> stop());
        priority.setText("");
        monitors.setText(model.monitors());
        HBox header = new HBox(12, stop, new Label(model.header()), priority, monitors);
        header.setAlignment(javafx.geometry.Pos.CENTER_LEFT);
        VBox running = new VBox(4, header, referee.node());
        running.setPadding(new Insets(4));
        root.setCenter(running);
        // the pressed Start button is gone: keep the keyboard in this tab, or it would go to the
        // first field of another view, and the dock would show that view instead of this one
        referee.node().requestFocus();
    }

    private void stop() {
        setupMessage.setText(model.stop());
        referee = null;
        root.setCenter(setup);
        format.requestFocus();
    }

    private void toggleOverride() {
        model.override(override.isSelected(), overrideReason.getText()).ifPresent(refused -> {
            override.setSelected(false);
            matchNotice.setText(refused);
        });
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        model.stopped().ifPresent(setupMessage::setText);
        model.started().ifPresent(line -> {
            setupMessage.setText(line);
            if (model.shown() != null) {
                show(model.shown());
            }
        });
        if (model.follow()) {
            if (model.shown() == null) {
                referee = null;
                root.setCenter(setup);
            } else {
                show(model.shown());
            }
        }
        if (referee != null) {
            referee.refresh(frame);
            priority.setText(model.priority());
            String line = model.monitors();
            if (!line.equals(monitors.getText())) {
                monitors.setText(line);
            }
        }
        GameControllerTabModel.Notice notice = model.matchNotice();
        matchNotice.setText(notice.text());
        matchNoticeTip.setText(notice.text());
        matchNotice.setStyle(notice.warning() ? "-fx-text-fill: #e0a000; -fx-font-weight: bold;" : "");
    }

    @Override
    public void close() {
        // The GameController keeps running when its tab closes; the console owns it.
    }
}
