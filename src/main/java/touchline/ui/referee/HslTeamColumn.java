package touchline.ui.referee;

import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import touchline.game.LeagueAction;
import touchline.game.hsl.HslState;
import touchline.game.hsl.SetPlay;
import touchline.protocol.gamecontroller.TeamColour;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * One side of the HSL referee box: the team on that side now (they swap at half time) with
 * its name, field player and goalkeeper colours, score, message budget and timeouts, its set
 * plays, and a row per robot (jersey, penalty and its seconds, cautions, liveness, and the
 * button that gives the chosen call or starts the timer / lets the robot back).
 */
final class HslTeamColumn {

    static final String MONO = "-fx-font-family: monospace;";
    /** Team and robot buttons: two teams of five robots and nine set plays fit a 1280×720 window. */
    static final String COMPACT = "-fx-padding: 2 6 2 6;";

    private final HslRefereeModel model;
    private final int side;
    private final VBox column = new VBox(6);
    private final List<Runnable> texts = new ArrayList<>();
    private final List<Consumer<JerseyLiveness>> robotTexts = new ArrayList<>();

    HslTeamColumn(HslRefereeModel model, RefereeButtons buttons, int side) {
        this.model = model;
        this.side = side;
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
        HBox head = new HBox(6, title, field, keeper);
        head.setAlignment(Pos.CENTER_LEFT);
        HBox scoreLine = new HBox(12, score, new VBox(2, colours, budget, timeouts));
        scoreLine.setAlignment(Pos.CENTER_LEFT);
        column.getChildren().addAll(head, scoreLine, setPlays(buttons),
                new Label("Robots (jersey, penalty, cautions, liveness)"), robots(buttons));
        column.setPadding(new Insets(0, 4, 0, 4));
        column.setMinWidth(Region.USE_PREF_SIZE);
    }

    private Node setPlays(RefereeButtons buttons) {
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
            Supplier<LeagueAction<? super HslState>> action = kind != null ? () -> model.setPlay(side, kind)
                    : kinds[i][0].equals("goal") ? () -> model.goal(side) : () -> model.timeout(side);
            Button b = buttons.button("gc-" + kinds[i][0] + "-" + side, kinds[i][1], action);
            b.setPrefWidth(140);
            b.setMinWidth(140);
            b.setStyle(COMPACT);
            plays.add(b, i % 2, i / 2);
        }
        return plays;
    }

    private Node robots(RefereeButtons buttons) {
        GridPane robots = new GridPane();
        robots.setHgap(4);
        robots.setVgap(2);
        for (int n = 1; n <= model.playersPerTeam(); n++) {
            int player = n;
            Label line = new Label();
            line.setId("gc-robot-text-" + side + "-" + n);
            line.setStyle(MONO);
            line.setMinWidth(Region.USE_PREF_SIZE);
            Button press = buttons.button("gc-robot-" + side + "-" + n, "", () -> model.robotAction(side, player),
                    () -> model.pressRobot(side, player));
            press.setPrefWidth(100);
            press.setMinWidth(100);
            press.setStyle(COMPACT);
            robotTexts.add(liveness -> {
                line.setText(model.robotText(side, player, liveness.status(model.teamNumber(side), player)));
                press.setText(model.robotButtonText(side, player));
            });
            robots.addRow(n - 1, line, press);
        }
        return robots;
    }

    Node node() {
        return column;
    }

    void refresh(JerseyLiveness liveness) {
        for (Runnable t : texts) {
            t.run();
        }
        for (var t : robotTexts) {
            t.accept(liveness);
        }
    }

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
}
