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
import touchline.app.Referee;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.app.game.MatchMode;
import touchline.game.RefereedGame;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslRules;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.SenderPriority;
import touchline.transport.HostPort;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;
import touchline.transport.gamecontroller.MonitorStats;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;

/**
 * The GameController tab: set up a practice game (format, teams, for HSL the competition and
 * colours, where to send; remembered for the next start), start the console's embedded
 * GameController and referee it with {@link HslRefereeView} (HSL 2026, the default) or
 * {@link GameControllerView} (the older formats); and, always, match mode's state with its
 * explicit, logged override switch.
 */
public final class GameControllerTab implements View {

    /** Default destinations, e.g. the demo team's robot ports; else the official broadcast. */
    public static final String DESTINATIONS_PROPERTY = "touchline.gc.dest";

    private final Referee refereeing;
    private final LiveField field;
    private final BorderPane root = new BorderPane();
    private final ComboBox<String> format = new ComboBox<>();
    private final TextField teamA = new TextField("13");
    private final TextField teamB = new TextField("7");
    private final TextField destinations = new TextField(System.getProperty(DESTINATIONS_PROPERTY,
            GcConfig.DEFAULT_BROADCAST + ":" + GcProfile.GAME_STATE_PORT));
    private final TextField returnPort = new TextField("");
    private final CheckBox realtime = new CheckBox("Real-time priority for the sender");
    private final HslSetup hsl = new HslSetup();
    private final RememberedSetup remembered;
    private final Label setupMessage = new Label();
    private final Label priority = new Label();
    private final Label monitors = new Label();
    private final Label matchNotice = new Label();
    private final javafx.scene.control.Tooltip matchNoticeTip = new javafx.scene.control.Tooltip();
    private final CheckBox override = new CheckBox("Override match mode (logged)");
    private final TextField overrideReason = new TextField();
    private final VBox setup;
    private View referee;
    private String monitorLine = "";
    private EmbeddedGameController shown;
    private final touchline.ui.frame.ConsoleStatus status;

    public GameControllerTab(ViewContext context, ViewSource source) {
        this.refereeing = context.referee();
        this.field = context.field();
        this.status = context.status();
        this.remembered = new RememberedSetup(context.settingsDir());
        root.setId("gamecontroller-tab");
        for (GcProfile p : GcProfile.values()) {
            format.getItems().add(p.cliName());
        }
        // HSL 2026 first: GcProfile lists hsl20 first, the official GameController's format since RoboCup 2026
        format.setValue(GcProfile.values()[0].cliName());
        format.valueProperty().addListener((o, was, now) -> hsl.showFor(GcProfile.parse(now)));
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
        start.setDefaultButton(true);
        start.setOnAction(e -> start());
        // On by default: a crowded laptop must not move the 500 ms cadence (Linux, root or
        // CAP_SYS_NICE; where it is not granted the running tab says why).
        realtime.setSelected(true);
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
        remembered.restore(format, teamA, teamB, destinations, returnPort, hsl);
        hsl.showFor(GcProfile.parse(format.getValue()));
    }

    private void start() {
        try {
            GcProfile profile = GcProfile.parse(format.getValue());
            if (profile == null) {
                setupMessage.setText("choose a format");
                return;
            }
            List<InetSocketAddress> dests = new ArrayList<>();
            for (String d : destinations.getText().split(",")) {
                if (!d.isBlank()) {
                    dests.add(HostPort.parse(d, GcProfile.GAME_STATE_PORT).resolved());
                }
            }
            if (dests.isEmpty()) {
                setupMessage.setText("give at least one destination");
                return;
            }
            int a = Integer.parseInt(teamA.getText().strip());
            int b = Integer.parseInt(teamB.getText().strip());
            GcConfig defaults = GcConfig.defaults(profile);
            int returns = returnPort.getText().isBlank() ? profile.defaultReturnPort() : Integer.parseInt(returnPort.getText().strip());
            GcConfig config = new GcConfig(profile, false, dests, null, new InetSocketAddress("0.0.0.0", returns),
                    defaults.rivalBind(), GcConfig.INTERVAL_MS, realtime.isSelected());
            RefereedGame game;
            if (profile.hsl()) {
                String wrong = a == b ? "the two teams need different numbers" : hsl.conflict();
                if (wrong != null) {
                    setupMessage.setText("cannot start: " + wrong);
                    return;
                }
                game = new HslGame(HslRules.forVersion(profile.hslVersion(), hsl.competition()), a, hsl.coloursA(), b,
                        hsl.coloursB(), refereeing.gameClock());
            } else {
                game = new Game(LeagueParams.hlSimulationKidSize(), a, 1, b, 0, refereeing.gameClock());
            }
            Integer monitorPort = profile.hsl() ? hsl.monitorPort() : null;
            remembered.save(format, teamA, teamB, destinations, returnPort, hsl);
            EmbeddedGameController gc = refereeing.start(game, config);
            monitorLine = monitorPort == null ? "" : serveMonitors(gc, monitorPort);
            show(gc);
        } catch (NumberFormatException e) {
            setupMessage.setText("team numbers and ports are whole numbers: " + e.getMessage());
        } catch (IOException | RuntimeException e) {
            setupMessage.setText("cannot start: " + e.getMessage());
        }
    }

    /** Answers monitors as the official GameController does; a busy port costs only that (said in the tab). */
    private static String serveMonitors(EmbeddedGameController gc, int port) {
        try {
            gc.serveMonitors(new InetSocketAddress("0.0.0.0", port), GcProfile.GAME_STATE_PORT, ForwardedReturnPacket.PORT);
            return "monitors register on UDP " + gc.monitorRequestAddress().getPort();
        } catch (IOException e) {
            return "no monitors: cannot listen on UDP " + port + " (" + e.getMessage() + ")";
        }
    }

    /** Shows the referee controls of a running GameController (started here or elsewhere). */
    private void show(EmbeddedGameController gc) {
        shown = gc;
        referee = gc.hsl() ? new HslRefereeView(new HslRefereeModel(gc.runtime()), gc, field)
                : new GameControllerView(gc.runtime(), gc);
        Button stop = new Button("Stop GameController");
        stop.setId("gc-stop");
        stop.setOnAction(e -> stop());
        priority.setText("");
        monitors.setText(monitorLine);
        HBox header = new HBox(12, stop, new Label(gc.config().profile().cliName() + " to " + gc.config().destinations()),
                priority, monitors);
        header.setAlignment(javafx.geometry.Pos.CENTER_LEFT);
        VBox running = new VBox(4, header, referee.node());
        running.setPadding(new Insets(4));
        root.setCenter(running);
        // the pressed Start button is gone: keep the keyboard in this tab, or it would go to the
        // first field of another view, and the dock would show that view instead of this one
        referee.node().requestFocus();
    }

    private void stop() {
        refereeing.stop();
        referee = null;
        shown = null;
        root.setCenter(setup);
        format.requestFocus();
        setupMessage.setText("stopped");
    }

    private void toggleOverride() {
        MatchMode mm = refereeing.matchMode();
        if (override.isSelected() && overrideReason.getText().isBlank()) {
            override.setSelected(false);
            matchNotice.setText("An override needs a reason; it is logged.");
            return;
        }
        mm.setOverride(override.isSelected(), overrideReason.getText().strip());
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        EmbeddedGameController running = refereeing.gameController().orElse(null);
        if (running != shown) {
            if (running == null) {
                referee = null;
                shown = null;
                root.setCenter(setup);
            } else {
                monitorLine = ""; // started elsewhere: whoever started it serves monitors or not
                show(running);
            }
        }
        if (referee != null) {
            referee.refresh(frame);
            priority.setText(priorityText(shown.senderPriority()));
            MonitorStats served = shown.monitorStats();
            String line = served == null || monitorLine.isEmpty() ? monitorLine : monitorLine + "; "
                    + served.monitors() + " of " + served.capacity() + " registered, "
                    + (served.refusedFull() + served.badRequests()) + " refused";
            if (!line.equals(monitors.getText())) {
                monitors.setText(line);
            }
        }
        String notice = refereeing.matchMode().notice();
        // the same words as the status bar: attempts held back (retries count) beside the requests waiting now
        int waiting = status.waitingNow();
        matchNotice.setText(notice.isEmpty() ? "Match mode: no game on; the console may talk to the robots."
                : notice + "; " + (waiting == 1 ? "1 request waiting now" : waiting + " requests waiting now"));
        matchNoticeTip.setText(matchNotice.getText());
        matchNotice.setStyle(notice.isEmpty() ? "" : "-fx-text-fill: #e0a000; -fx-font-weight: bold;");
    }

    private static String priorityText(SenderPriority p) {
        return switch (p.kind()) {
            case REAL_TIME -> "Sender: real-time priority (500 ms cadence held under load)";
            case NOT_REQUESTED -> "Sender: normal priority";
            case STARTING -> "Sender: starting";
            case REFUSED -> "Sender: normal priority, real-time refused (" + p.why() + ")";
        };
    }

    @Override
    public void close() {
        // The GameController keeps running when its tab closes; the console owns it.
    }
}
