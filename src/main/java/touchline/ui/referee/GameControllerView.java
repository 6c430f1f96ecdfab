package touchline.ui.referee;

import javafx.geometry.Insets;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;
import javafx.scene.layout.FlowPane;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import touchline.game.Action;
import touchline.game.Card;
import touchline.game.DropBall;
import touchline.game.GameState;
import touchline.game.Goal;
import touchline.game.LeagueAction;
import touchline.game.LeagueParams;
import touchline.game.Outcome;
import touchline.game.Penalize;
import touchline.game.Penalty;
import touchline.game.PlayerState;
import touchline.game.SecondaryState;
import touchline.game.SetPlayStep;
import touchline.game.StartSetPlay;
import touchline.game.TeamState;
import touchline.game.Timeout;
import touchline.game.ToFinished;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.game.Unpenalize;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.GameRuntime;
import touchline.app.game.RefereeSnapshot;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The referee's GameController tab: the clock and state in large type, big buttons for every
 * action (keys R S P F D for ready/set/play/finish/dropped ball, Ctrl+Z undo), per team its
 * set plays and each robot's penalty, countdown, cards and liveness with a penalise/unpenalise
 * button. Buttons only build actions and enqueue them to the game's {@link GameRuntime}; the
 * frame pulse pulls the owner's snapshot and the outcome once the owner answered, so the JavaFX
 * thread never waits for the game and the view never receives callbacks from network threads. A second GameController
 * on the network shows as a red banner.
 */
public final class GameControllerView implements View {

    private final GameRuntime game;
    private final EmbeddedGameController gc;
    private final RefereeOutcomes outcomes;
    private final VBox root = new VBox(8);
    private final Label warning = new Label();
    private final Label clock = new Label();
    private final Label message = new Label();
    private final List<Label> teamTitles = new ArrayList<>();
    private final List<List<Label>> robotLabels = new ArrayList<>();
    private final List<List<Button>> robotButtons = new ArrayList<>();

    /**
     * @param game the owner of an HL/SPL game: buttons enqueue to it, frames read its snapshot
     * @param gc   the running GameController for liveness and rival warnings; null shows neither
     */
    public GameControllerView(GameRuntime game, EmbeddedGameController gc) {
        this.game = game;
        this.gc = gc;
        this.outcomes = new RefereeOutcomes(game::now);
        root.setPadding(new Insets(8));
        root.setId("gamecontroller");
        warning.setId("gc-warning");
        warning.setStyle("-fx-background-color: #c00; -fx-text-fill: white; -fx-font-size: 18px; "
                + "-fx-font-weight: bold; -fx-padding: 6;");
        warning.setWrapText(true);
        clock.setId("gc-clock");
        clock.setStyle("-fx-font-size: 28px; -fx-font-family: monospace; -fx-font-weight: bold;");
        message.setId("gc-message");
        FlowPane states = new FlowPane(6, 6,
                button("gc-ready", "Ready (R)", ToReady::new),
                button("gc-set", "Set (S)", ToSet::new),
                button("gc-play", "Play (P)", ToPlaying::new),
                button("gc-finish", "Finish (F)", ToFinished::new),
                button("gc-dropball", "Dropped ball (D)", DropBall::new),
                button("gc-setplay-ready", "Set play: ready", () -> new SetPlayStep(SetPlayStep.Step.READY)),
                button("gc-prepare", "Prepare", () -> new SetPlayStep(SetPlayStep.Step.PREPARE)),
                button("gc-execute", "Execute", () -> new SetPlayStep(SetPlayStep.Step.EXECUTE)),
                button("gc-abort", "Abort", () -> new SetPlayStep(SetPlayStep.Step.ABORT)));
        Button undo = new Button("Undo (Ctrl+Z)");
        undo.setId("gc-undo");
        undo.setOnAction(e -> ask(game.undo()));
        states.getChildren().add(undo);
        HBox teams = new HBox(24, teamColumn(0), teamColumn(1));
        root.getChildren().addAll(warning, clock, states, teams, message);
        root.addEventFilter(KeyEvent.KEY_PRESSED, this::key);
        refresh(null);
    }

    private Button button(String id, String text, java.util.function.Supplier<LeagueAction<? super GameState>> action) {
        Button b = new Button(text);
        b.setId(id);
        b.setMinHeight(40);
        b.setStyle("-fx-font-size: 15px;");
        b.setOnAction(e -> ask(game.perform(action.get())));
        return b;
    }

    /** One side's column; actions name the team that is on that side at the time of the click. */
    private Node teamColumn(int side) {
        Label title = new Label();
        title.setStyle("-fx-font-size: 20px; -fx-font-weight: bold;");
        teamTitles.add(title);
        FlowPane plays = new FlowPane(4, 4,
                button("gc-goal-" + side, "Goal", () -> new Goal(team(side))),
                button("gc-freekick-" + side, "Free kick",
                        () -> new StartSetPlay(team(side), SecondaryState.DIRECT_FREEKICK)),
                button("gc-corner-" + side, "Corner", () -> new StartSetPlay(team(side), SecondaryState.CORNER_KICK)),
                button("gc-goalkick-" + side, "Goal kick",
                        () -> new StartSetPlay(team(side), SecondaryState.GOAL_KICK)),
                button("gc-throwin-" + side, "Throw-in", () -> new StartSetPlay(team(side), SecondaryState.THROW_IN)),
                button("gc-penaltykick-" + side, "Penalty kick",
                        () -> new StartSetPlay(team(side), SecondaryState.PENALTYKICK)),
                button("gc-timeout-" + side, "Timeout", () -> new Timeout(team(side))));
        plays.setPrefWrapLength(320);
        GridPane robots = new GridPane();
        robots.setHgap(6);
        robots.setVgap(2);
        List<Label> labels = new ArrayList<>();
        List<Button> buttons = new ArrayList<>();
        for (int n = 1; n <= LeagueParams.MAX_PLAYERS; n++) {
            int player = n;
            Label l = new Label();
            l.setStyle("-fx-font-family: monospace;");
            Button pen = new Button();
            pen.setId("gc-robot-" + side + "-" + n);
            pen.setOnAction(e -> ask(game.perform(togglePenalty(side, player))));
            Button yellow = new Button("Yellow");
            yellow.setOnAction(e -> ask(game.perform(new Card(team(side), player, Card.Kind.YELLOW))));
            robots.addRow(n - 1, l, pen, yellow);
            labels.add(l);
            buttons.add(pen);
        }
        robotLabels.add(labels);
        robotButtons.add(buttons);
        return new VBox(6, title, plays, robots);
    }

    private int team(int side) {
        return game.snapshot().hl().teamOnSide(side).number();
    }

    private Action togglePenalty(int side, int player) {
        TeamState t = game.snapshot().hl().teamOnSide(side);
        return t.player(player).isPenalised() ? new Unpenalize(t.number(), player)
                : new Penalize(t.number(), player, Penalty.PHYSICAL_CONTACT);
    }

    private void key(KeyEvent e) {
        Action a = null;
        if (e.isShortcutDown() && e.getCode() == KeyCode.Z) {
            ask(game.undo());
            e.consume();
            return;
        }
        switch (e.getCode()) {
            case R -> a = new ToReady();
            case S -> a = new ToSet();
            case P -> a = new ToPlaying();
            case F -> a = new ToFinished();
            case D -> a = new DropBall();
            default -> { }
        }
        if (a != null) {
            ask(game.perform(a));
            e.consume();
        }
    }

    /** An action just enqueued: its outcome is shown by the frame after the owner answered. */
    private void ask(CompletableFuture<Outcome> outcome) {
        outcomes.expect(outcome);
        refresh(null);
    }

    @Override
    public Node node() {
        return root;
    }

    /** Robot {@code player}'s line on {@code side} as shown (for tests). */
    public String robotText(int side, int player) {
        return robotLabels.get(side).get(player - 1).getText();
    }

    @Override
    public void refresh(FrameContext frame) {
        outcomes.pull(); // first: the snapshot is published before an outcome comes
        String style = outcomes.refused() ? "-fx-text-fill: #c00;" : "";
        if (!outcomes.message().equals(message.getText()) || !style.equals(message.getStyle())) {
            message.setText(outcomes.message());
            message.setStyle(style);
        }
        RefereeSnapshot snapshot = game.snapshot();
        GameState s = snapshot.hl();
        long now = game.now();
        String rival = gc == null ? "" : gc.rivalWarning();
        warning.setText(rival);
        warning.setVisible(!rival.isEmpty());
        warning.setManaged(!rival.isEmpty());
        clock.setText(s.describe(now));
        for (int side = 0; side < 2; side++) {
            TeamState t = s.teamOnSide(side);
            teamTitles.get(side).setText("Team " + t.number() + "  " + t.score() + (side == 0 ? "  (left)" : "  (right)"));
            for (int n = 1; n <= LeagueParams.MAX_PLAYERS; n++) {
                PlayerState p = t.player(n);
                String live = gc == null ? "" : " " + gc.liveness().status(t.number(), n, now);
                String penalty = p.penalty() == Penalty.NONE ? "playing" : p.penalty().name().toLowerCase(java.util.Locale.ROOT)
                        + (p.penalty().timed() ? " " + p.secsTillUnpenalised(now) + "s" : "");
                robotLabels.get(side).get(n - 1).setText(String.format("%2d%s %-26s W%d Y%d R%d%s", n,
                        p.goalkeeper() ? " GK" : "   ", penalty, p.warnings(), p.yellowCards(), p.redCards(), live));
                Button b = robotButtons.get(side).get(n - 1);
                b.setText(p.isPenalised() ? "Unpenalise" : "Penalise");
                b.setDisable(p.penalty() == Penalty.SUBSTITUTE);
            }
        }
    }
}
