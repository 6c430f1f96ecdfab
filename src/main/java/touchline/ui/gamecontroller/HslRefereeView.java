package touchline.ui.gamecontroller;

import javafx.event.EventHandler;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.TextInputControl;
import javafx.scene.control.ToggleButton;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import touchline.app.Console;
import touchline.game.hsl.HslAction;
import touchline.game.hsl.SetPlay;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.transport.gamecontroller.EmbeddedGameController;
import touchline.ui.FrameContext;
import touchline.ui.FramePulse;
import touchline.ui.View;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The referee box of an HSL 2026 game, laid out like the official GameController: each team
 * on its side with its colours, score, message budget, set plays and robots; in the middle
 * the clocks, the big Stop/Resume and the penalty calls (a call first, then the robot). Keys
 * work whatever has focus while the tab is shown (a filter on the scene, idle while the tab is
 * hidden or text is being typed): Space stop/resume, R ready, S set, P play, B ball free,
 * D dropped ball, A additional minute, Esc cancel the call, Ctrl+Z undo. Every button only
 * dispatches its action through {@link HslRefereeModel}; each frame pulls the state and
 * enables the buttons the rules allow. Texts that count down are monospace at a fixed width,
 * so no button moves.
 */
public final class HslRefereeView implements View {

    private static final String BIG = "-fx-font-size: 15px;";
    private static final String MONO = "-fx-font-family: monospace;";
    /** Team and robot buttons: two teams of seven robots and nine set plays fit a 1280×720 window. */
    private static final String COMPACT = "-fx-padding: 2 6 2 6;";

    private final HslRefereeModel model;
    private final EmbeddedGameController gc;
    private final Console console;
    private final BorderPane root = new BorderPane();
    private final Label warning = new Label();
    private final Label state = new Label();
    private final Label clock = new Label();
    private final Label secondary = new Label();
    private final Label message = new Label();
    private final Button stopResume = new Button();
    private final List<Bound> bound = new ArrayList<>();
    private final List<Runnable> texts = new ArrayList<>();
    private final List<ToggleButton> calls = new ArrayList<>();
    private final EventHandler<KeyEvent> keys = this::key;

    /** A button and the action it dispatches, enabled when that action is legal. */
    private record Bound(Button button, Supplier<HslAction> action) {
    }

    /**
     * @param gc      the running GameController (liveness from return packets, rival warning), or null
     * @param console the console whose robots the Robots view lists, or null
     */
    public HslRefereeView(HslRefereeModel model, EmbeddedGameController gc, Console console) {
        this.model = model;
        this.gc = gc;
        this.console = console;
        root.setId("gamecontroller-hsl");
        root.setPadding(new Insets(4));
        warning.setId("gc-warning");
        warning.setStyle("-fx-background-color: #c00; -fx-text-fill: white; -fx-font-size: 16px; "
                + "-fx-font-weight: bold; -fx-padding: 4;");
        warning.setWrapText(true);
        root.setTop(warning);
        root.setLeft(team(0));
        root.setRight(team(1));
        root.setCenter(centre());
        message.setId("gc-message");
        message.setWrapText(true);
        message.setMinHeight(20);
        message.setMaxWidth(Double.MAX_VALUE);
        message.setAlignment(Pos.CENTER);
        message.setStyle("-fx-font-size: 14px;");
        root.setBottom(message);
        root.sceneProperty().addListener((o, was, now) -> {
            if (was != null) {
                was.removeEventFilter(KeyEvent.KEY_PRESSED, keys);
            }
            if (now != null) {
                now.addEventFilter(KeyEvent.KEY_PRESSED, keys);
            }
        });
        refresh(null);
    }

    private Node centre() {
        state.setId("gc-state");
        state.setStyle("-fx-font-size: 14px; -fx-font-weight: bold;");
        state.setAlignment(Pos.CENTER);
        clock.setId("gc-clock");
        clock.setStyle("-fx-font-size: 40px; -fx-font-weight: bold; " + MONO);
        secondary.setId("gc-secondary");
        secondary.setStyle("-fx-font-size: 22px; " + MONO);
        stopResume.setId("gc-stop-resume");
        stopResume.setPrefSize(300, 46);
        stopResume.setMinSize(300, 46);
        stopResume.setOnAction(e -> act(() -> model.perform(model.stopOrResume())));
        bound.add(new Bound(stopResume, model::stopOrResume));
        HBox flow = new HBox(4, button("gc-ready", "Ready (R)", model::ready), button("gc-set", "Set (S)", model::set),
                button("gc-play", "Play (P)", model::play), button("gc-ballfree", "Ball free (B)", model::ballFree));
        flow.setAlignment(Pos.CENTER);
        HBox more = new HBox(4, button("gc-dropball", "Dropped ball (D)", model::droppedBall),
                button("gc-additional-minute", "+1 min (A)", model::additionalMinute),
                button("gc-referee-timeout", "Referee timeout", model::refereeTimeout));
        more.setAlignment(Pos.CENTER);
        Button undo = new Button("Undo (Ctrl+Z)");
        undo.setId("gc-undo");
        undo.setOnAction(e -> act(model::undo));
        HBox halves = new HBox(4, button("gc-finish", "Finish half", model::finishHalf),
                button("gc-second-half", "Second half", model::secondHalf), undo);
        halves.setAlignment(Pos.CENTER);
        GridPane penalties = new GridPane();
        penalties.setHgap(4);
        penalties.setVgap(3);
        penalties.setAlignment(Pos.CENTER);
        List<HslPenalty> all = model.calls();
        for (int i = 0; i < all.size(); i++) {
            HslPenalty call = all.get(i);
            ToggleButton t = new ToggleButton(HslRefereeModel.buttonLabel(call));
            t.setStyle(COMPACT);
            t.setId("gc-call-" + call.name().toLowerCase(Locale.ROOT));
            t.setUserData(call);
            t.setPrefWidth(134);
            t.setMinWidth(134);
            t.setOnAction(e -> act(() -> model.choose(call)));
            calls.add(t);
            penalties.add(t, i % 3, i / 3);
        }
        HBox clocks = new HBox(16, clock, secondary);
        clocks.setAlignment(Pos.BASELINE_CENTER);
        // the hint "call first, then the robot" is the message line once a call is chosen
        VBox centre = new VBox(5, state, clocks, stopResume, flow, more, halves, penalties);
        centre.setAlignment(Pos.TOP_CENTER);
        centre.setPadding(new Insets(0, 8, 0, 8));
        return centre;
    }

    /** Does what the referee asked and shows it at once (the next robot button is enabled without waiting a frame). */
    private void act(Runnable referee) {
        referee.run();
        refresh(null);
    }

    private Button button(String id, String text, Supplier<HslAction> action) {
        Button b = new Button(text);
        b.setId(id);
        b.setOnAction(e -> act(() -> model.perform(action.get())));
        bound.add(new Bound(b, action));
        return b;
    }

    private Node team(int side) {
        Label title = new Label();
        title.setStyle("-fx-font-size: 18px; -fx-font-weight: bold;");
        Region field = swatch();
        Region keeper = swatch();
        Label colours = new Label();
        Label score = new Label();
        score.setId("gc-score-" + side);
        score.setStyle("-fx-font-size: 32px; -fx-font-weight: bold; " + MONO);
        Label budget = new Label();
        budget.setId("gc-budget-" + side);
        budget.setStyle(MONO);
        Label timeouts = new Label();
        texts.add(() -> {
            title.setText(model.teamTitle(side));
            colours.setText(model.colours(side));
            fill(field, model.state().teamOnSide(side).fieldColour());
            fill(keeper, model.state().teamOnSide(side).goalkeeperColour());
            score.setText(model.score(side));
            budget.setText(model.budget(side));
            timeouts.setText(model.timeoutsLeft(side));
        });
        GridPane plays = new GridPane();
        plays.setHgap(4);
        plays.setVgap(3);
        String[][] kinds = {{"kickoff", "Kick-off"}, {"goal", "Goal"}, {"directfreekick", "Direct free kick"},
                {"indirectfreekick", "Indirect free kick"}, {"throwin", "Throw-in"}, {"goalkick", "Goal kick"},
                {"corner", "Corner kick"}, {"penaltykick", "Penalty kick"}, {"timeout", "Timeout"}};
        SetPlay[] setPlays = {SetPlay.KICK_OFF, null, SetPlay.DIRECT_FREE_KICK, SetPlay.INDIRECT_FREE_KICK,
                SetPlay.THROW_IN, SetPlay.GOAL_KICK, SetPlay.CORNER_KICK, SetPlay.PENALTY_KICK, null};
        for (int i = 0; i < kinds.length; i++) {
            SetPlay kind = setPlays[i];
            Supplier<HslAction> action = kind != null ? () -> model.setPlay(side, kind)
                    : kinds[i][0].equals("goal") ? () -> model.goal(side) : () -> model.timeout(side);
            Button b = button("gc-" + kinds[i][0] + "-" + side, kinds[i][1], action);
            b.setPrefWidth(140);
            b.setMinWidth(140);
            b.setStyle(COMPACT);
            plays.add(b, i % 2, i / 2);
        }
        GridPane robots = new GridPane();
        robots.setHgap(4);
        robots.setVgap(2);
        for (int n = 1; n <= model.playersPerTeam(); n++) {
            int player = n;
            Label line = new Label();
            line.setId("gc-robot-text-" + side + "-" + n);
            line.setStyle(MONO);
            line.setMinWidth(Region.USE_PREF_SIZE);
            Button press = button("gc-robot-" + side + "-" + n, "", () -> model.robotAction(side, player));
            press.setOnAction(e -> act(() -> model.pressRobot(side, player)));
            press.setPrefWidth(100);
            press.setMinWidth(100);
            press.setStyle(COMPACT);
            texts.add(() -> {
                line.setText(model.robotText(side, player, liveness.status(model.teamNumber(side), player)));
                press.setText(model.robotButtonText(side, player));
            });
            robots.addRow(n - 1, line, press);
        }
        HBox head = new HBox(6, title, field, keeper);
        head.setAlignment(Pos.CENTER_LEFT);
        HBox scoreLine = new HBox(12, score, new VBox(2, colours, budget, timeouts));
        scoreLine.setAlignment(Pos.CENTER_LEFT);
        VBox column = new VBox(6, head, scoreLine, plays, new Label("Robots (jersey, penalty, cautions, liveness)"),
                robots);
        column.setPadding(new Insets(0, 4, 0, 4));
        column.setMinWidth(Region.USE_PREF_SIZE);
        HBox.setHgrow(column, Priority.NEVER);
        return column;
    }

    private JerseyLiveness liveness = new JerseyLiveness(List.of(), null, 0);

    private static Region swatch() {
        Region r = new Region();
        r.setMinSize(18, 18);
        r.setPrefSize(18, 18);
        r.setMaxSize(18, 18);
        return r;
    }

    private static void fill(Region swatch, TeamColour colour) {
        swatch.setStyle("-fx-border-color: #888; -fx-background-color: " + css(colour) + ";");
    }

    private static String css(TeamColour c) {
        return switch (c) {
            case BLUE -> "#1f5fd1";
            case RED -> "#d0202a";
            case YELLOW -> "#f2d21b";
            case BLACK -> "#111";
            case WHITE -> "#fff";
            case GREEN -> "#2a9a3a";
            case ORANGE -> "#f08a1c";
            case PURPLE -> "#8a3ab9";
            case BROWN -> "#7a4a1e";
            case GRAY -> "#888";
        };
    }

    private void key(KeyEvent e) {
        if (!FramePulse.showing(root) || e.getTarget() instanceof TextInputControl
                || (root.getScene() != null && root.getScene().getFocusOwner() instanceof TextInputControl)) {
            return; // the tab is hidden, or the user types a number somewhere
        }
        if (e.isShortcutDown() && e.getCode() == KeyCode.Z) {
            act(model::undo);
            e.consume();
            return;
        }
        if (e.isShortcutDown() || e.isAltDown()) {
            return;
        }
        HslAction action = switch (e.getCode()) {
            case SPACE -> model.stopOrResume();
            case R -> model.ready();
            case S -> model.set();
            case P -> model.play();
            case B -> model.ballFree();
            case D -> model.droppedBall();
            case A -> model.additionalMinute();
            default -> null;
        };
        if (e.getCode() == KeyCode.ESCAPE && model.chosen() != null) {
            act(() -> model.choose(null));
            e.consume();
        } else if (action != null) {
            act(() -> model.perform(action));
            e.consume();
        }
    }

    public HslRefereeModel model() {
        return model;
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        model.refresh();
        String rival = gc == null ? "" : gc.rivalWarning();
        warning.setText(rival);
        warning.setVisible(!rival.isEmpty());
        warning.setManaged(!rival.isEmpty());
        liveness = new JerseyLiveness(console == null ? List.of() : console.robots().robots(),
                gc == null ? null : gc.liveness(), model.game().now());
        state.setText(model.stateText());
        clock.setText(model.mainClock());
        secondary.setText(model.secondaryClock());
        boolean stopped = model.state().stopped();
        stopResume.setText(model.stopOrResumeLabel());
        stopResume.setStyle("-fx-font-size: 20px; -fx-font-weight: bold; -fx-text-fill: white; -fx-background-color: "
                + (stopped ? "#2a9a3a" : "#c0392b") + ";");
        for (Runnable t : texts) {
            t.run();
        }
        for (Bound b : bound) {
            b.button().setDisable(!model.legal(b.action().get()));
        }
        for (ToggleButton t : calls) {
            HslPenalty call = (HslPenalty) t.getUserData();
            t.setSelected(call == model.chosen());
            t.setDisable(!model.penaltyLegal(call));
        }
        message.setText(model.message());
        message.setStyle(model.refused() ? "-fx-font-size: 14px; -fx-text-fill: #e03030; -fx-font-weight: bold;"
                : "-fx-font-size: 14px;");
    }
}
