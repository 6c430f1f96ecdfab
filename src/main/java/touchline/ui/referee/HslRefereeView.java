package touchline.ui.referee;

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
import javafx.scene.layout.VBox;
import touchline.app.LiveField;
import touchline.game.LeagueAction;
import touchline.game.hsl.HslState;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.app.game.EmbeddedGameController;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.FramePulse;
import touchline.ui.frame.View;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The referee box of an HSL 2026 game, laid out like the official GameController: each team
 * on its side ({@link HslTeamColumn}); in the middle the clocks, the big Stop/Resume and the
 * penalty calls (a call first, then the robot). Keys work whatever has focus while the tab is
 * shown (a filter on the scene, idle while the tab is hidden or text is being typed): Space
 * stop/resume, R ready, S set, P play, B ball free, D dropped ball, A additional minute, Esc
 * cancel the call, Ctrl+Z undo. Buttons only dispatch actions through {@link HslRefereeModel};
 * each frame pulls the state and enables what the rules allow. Texts that count down are
 * monospace at a fixed width, so no button moves.
 */
public final class HslRefereeView implements View {

    private final HslRefereeModel model;
    private final EmbeddedGameController gc;
    private final LiveField field;
    private final RefereeButtons buttons;
    private final BorderPane root = new BorderPane();
    private final Label warning = new Label();
    private final Label state = new Label();
    private final Label clock = new Label();
    private final Label secondary = new Label();
    private final Label message = new Label();
    private final Button stopResume;
    private final List<HslTeamColumn> teams = new ArrayList<>();
    private final List<ToggleButton> calls = new ArrayList<>();
    private final EventHandler<KeyEvent> keys = this::key;

    /**
     * @param gc      the running GameController (liveness from return packets, rival warning), or null
     * @param field   the field whose robots the Robots view lists, or null
     */
    public HslRefereeView(HslRefereeModel model, EmbeddedGameController gc, LiveField field) {
        this.model = model;
        this.gc = gc;
        this.field = field;
        this.buttons = new RefereeButtons(model, () -> refresh(null));
        this.stopResume = buttons.button("gc-stop-resume", "", model::stopOrResume);
        root.setId("gamecontroller-hsl");
        root.setPadding(new Insets(4));
        warning.setId("gc-warning");
        warning.setStyle("-fx-background-color: #c00; -fx-text-fill: white; -fx-font-size: 16px; "
                + "-fx-font-weight: bold; -fx-padding: 4;");
        warning.setWrapText(true);
        root.setTop(warning);
        for (int side = 0; side < 2; side++) {
            teams.add(new HslTeamColumn(model, buttons, side));
        }
        root.setLeft(teams.get(0).node());
        root.setRight(teams.get(1).node());
        root.setCenter(centre());
        message.setId("gc-message");
        message.setWrapText(true);
        message.setMinHeight(20);
        message.setMaxWidth(Double.MAX_VALUE);
        message.setAlignment(Pos.CENTER);
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
        clock.setStyle("-fx-font-size: 40px; -fx-font-weight: bold; " + HslTeamColumn.MONO);
        secondary.setId("gc-secondary");
        secondary.setStyle("-fx-font-size: 22px; " + HslTeamColumn.MONO);
        stopResume.setPrefSize(300, 46);
        stopResume.setMinSize(300, 46);
        HBox flow = row(buttons.button("gc-ready", "Ready (R)", model::ready),
                buttons.button("gc-set", "Set (S)", model::set), buttons.button("gc-play", "Play (P)", model::play),
                buttons.button("gc-ballfree", "Ball free (B)", model::ballFree));
        HBox more = row(buttons.button("gc-dropball", "Dropped ball (D)", model::droppedBall),
                buttons.button("gc-additional-minute", "+1 min (A)", model::additionalMinute),
                buttons.button("gc-referee-timeout", "Referee timeout", model::refereeTimeout));
        Button undo = new Button("Undo (Ctrl+Z)");
        undo.setId("gc-undo");
        undo.setOnAction(e -> buttons.act(model::undo));
        HBox halves = row(buttons.button("gc-finish", "Finish half", model::finishHalf),
                buttons.button("gc-second-half", "Second half", model::secondHalf), undo);
        HBox clocks = new HBox(16, clock, secondary);
        clocks.setAlignment(Pos.BASELINE_CENTER);
        // the hint "call first, then the robot" is the message line once a call is chosen
        VBox centre = new VBox(5, state, clocks, stopResume, flow, more, halves, penalties());
        centre.setAlignment(Pos.TOP_CENTER);
        centre.setPadding(new Insets(0, 8, 0, 8));
        return centre;
    }

    private static HBox row(Node... nodes) {
        HBox row = new HBox(4, nodes);
        row.setAlignment(Pos.CENTER);
        return row;
    }

    private Node penalties() {
        GridPane penalties = new GridPane();
        penalties.setHgap(4);
        penalties.setVgap(3);
        penalties.setAlignment(Pos.CENTER);
        List<HslPenalty> all = model.calls();
        for (int i = 0; i < all.size(); i++) {
            HslPenalty call = all.get(i);
            ToggleButton t = new ToggleButton(HslRefereeModel.buttonLabel(call));
            t.setStyle(HslTeamColumn.COMPACT);
            t.setId("gc-call-" + call.name().toLowerCase(Locale.ROOT));
            t.setUserData(call);
            t.setPrefWidth(134);
            t.setMinWidth(134);
            t.setOnAction(e -> buttons.act(() -> model.choose(call)));
            calls.add(t);
            penalties.add(t, i % 3, i / 3);
        }
        return penalties;
    }

    private void key(KeyEvent e) {
        if (!FramePulse.showing(root) || e.getTarget() instanceof TextInputControl
                || (root.getScene() != null && root.getScene().getFocusOwner() instanceof TextInputControl)) {
            return; // the tab is hidden, or the user types a number somewhere
        }
        if (e.isShortcutDown() && e.getCode() == KeyCode.Z) {
            buttons.act(model::undo);
            e.consume();
            return;
        }
        if (e.isShortcutDown() || e.isAltDown()) {
            return;
        }
        RefereeKey key = RefereeKey.of(e.getCode()).orElse(null);
        if (key == RefereeKey.FORGET_CALL && model.chosen() != null) {
            buttons.act(() -> model.choose(null));
            e.consume();
        } else if (key != null && key.action(model) != null) {
            LeagueAction<? super HslState> action = key.action(model);
            buttons.act(() -> model.perform(action));
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
        JerseyLiveness liveness = new JerseyLiveness(field == null ? List.of() : field.robots().robots(),
                gc == null ? null : gc.liveness(), model.now());
        state.setText(model.stateText());
        clock.setText(model.mainClock());
        secondary.setText(model.secondaryClock());
        stopResume.setText(model.stopOrResumeLabel());
        stopResume.setStyle("-fx-font-size: 20px; -fx-font-weight: bold; -fx-text-fill: white; -fx-background-color: "
                + (model.state().stopped() ? "#2a9a3a" : "#c0392b") + ";");
        for (HslTeamColumn t : teams) {
            t.refresh(liveness);
        }
        buttons.refresh();
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
