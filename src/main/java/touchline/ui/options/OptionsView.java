package touchline.ui.options;

import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.TextField;
import javafx.scene.control.TreeCell;
import javafx.scene.control.TreeItem;
import javafx.scene.control.TreeView;
import javafx.scene.input.KeyCode;
import javafx.scene.input.MouseButton;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import touchline.model.OptionState;
import touchline.model.RobotOptions;
import touchline.model.RobotSnapshot;
import touchline.transport.SendResult;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ViewSpec;

import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * Per robot, the debug options it offers as a tree. Type to filter; Space (or a click on the
 * box) toggles the selected option; double-click (or Enter) opens the visualisation for its
 * data kind. Every state shown comes from the model: requesting the list, received, wanted,
 * streaming, and why the last command was held.
 */
public final class OptionsView implements View {

    /** A tree row: a robot (option == null) or one of its options. */
    /** @param replayed the row belongs to a replayed robot: shown only, never switched (it is not on the field) */
    public record Row(int robotId, String label, OptionState option, boolean replayed) {
        Row(int robotId, String label, OptionState option) {
            this(robotId, label, option, false);
        }
    }

    private final ViewContext context;
    private final TreeView<Row> tree = new TreeView<>(new TreeItem<>(new Row(-1, "robots", null)));
    private final TextField filter = new TextField();
    private final Label status = new Label();
    private final BorderPane root = new BorderPane();
    private final Map<Integer, Boolean> collapsed = new HashMap<>();
    private long seenOptions = -1;
    private long seenRobots = -1;
    private long readMicros = Long.MIN_VALUE;
    private boolean rebuild = true;

    public OptionsView(ViewContext context) {
        this.context = context;
        tree.setId("options-tree");
        tree.setShowRoot(false);
        tree.setCellFactory(t -> new TreeCell<>() {
            private final javafx.scene.control.CheckBox box = new javafx.scene.control.CheckBox();
            /** "in the game": the option goes into the robot's match digest during play */
            private final javafx.scene.control.CheckBox game = new javafx.scene.control.CheckBox("game");
            private final HBox boxes = new HBox(6, box, game);
            {
                game.getStyleClass().add("option-game-box");
                game.setFocusTraversable(false);
                game.setTooltip(new javafx.scene.control.Tooltip("In the game: sent in the robot's match digest "
                        + "(once a period during READY, SET and PLAYING); G on the keyboard"));
                game.setOnAction(e -> {
                    Row row = getItem();
                    game.setSelected(row != null && row.option() != null && row.option().matchRank() > 0);
                    if (row != null && row.option() != null) {
                        getTreeView().getSelectionModel().select(getTreeItem());
                        toggleGame(row);
                    }
                });
                box.getStyleClass().add("option-box");
                box.setFocusTraversable(false); // the tree keeps the keyboard: Space toggles there
                // a click on the box toggles that row's option (the box shows the model, never its own state)
                box.setOnAction(e -> {
                    Row row = getItem();
                    box.setSelected(row != null && row.option() != null && context.switches().shownOn(row.option()));
                    if (row != null && row.option() != null) {
                        getTreeView().getSelectionModel().select(getTreeItem());
                        toggle(row);
                    }
                });
            }

            @Override
            protected void updateItem(Row row, boolean empty) {
                super.updateItem(row, empty);
                setText(empty || row == null ? null : row.label());
                boolean option = !empty && row != null && row.option() != null;
                if (option) {
                    box.setSelected(context.switches().shownOn(row.option())); // a viewer: the serving console's view
                    box.setDisable(row.replayed());
                    game.setSelected(row.option().matchRank() > 0);
                    game.setDisable(row.replayed());
                }
                setGraphic(option ? boxes : null);
                setStyle(empty || row == null || row.option() == null ? "-fx-font-weight: bold;"
                        : row.option().streaming() ? "-fx-text-fill: #2da44e;" : "");
            }
        });
        // Back on this tab the tree takes the keyboard again with its selected row, so Space
        // works without a click first (the tab's content leaves and re-enters the scene).
        root.sceneProperty().addListener((o, was, now) -> {
            if (now != null) {
                javafx.application.Platform.runLater(this::focusTree);
            }
        });
        // a filter, not a handler: the tree's own key handling would take Space and Enter first
        tree.addEventFilter(javafx.scene.input.KeyEvent.KEY_PRESSED, e -> {
            if (e.getCode() == KeyCode.SPACE) {
                toggleSelected();
                e.consume();
            } else if (e.getCode() == KeyCode.G) {
                selectedOption().ifPresent(this::toggleGame);
                e.consume();
            } else if (e.getCode() == KeyCode.ENTER) {
                openSelected();
                e.consume();
            }
        });
        tree.setOnMouseClicked(e -> {
            if (e.getButton() == MouseButton.PRIMARY && e.getClickCount() == 2) {
                openSelected();
            }
        });
        filter.setPromptText("type to filter options");
        filter.setId("options-filter");
        filter.textProperty().addListener((o, a, b) -> rebuild = true);
        HBox.setHgrow(filter, Priority.ALWAYS);
        HBox bar = new HBox(8, filter);
        bar.setStyle("-fx-padding: 4 8 4 8;");
        root.setTop(bar);
        root.setCenter(tree);
        Label hint = new Label("Space or the box: on/off   G: in the game   Double-click or Enter: open visualisation   F1: help");
        status.setId("options-status");
        HBox bottom = new HBox(16, hint, status);
        bottom.setStyle("-fx-padding: 2 8 2 8;");
        root.setBottom(bottom);
    }

    private Optional<Row> selectedOption() {
        TreeItem<Row> item = tree.getSelectionModel().getSelectedItem();
        return item == null || item.getValue().option() == null ? Optional.empty() : Optional.of(item.getValue());
    }

    /** Flips the selected option's wanted state through the model (which sends the request). */
    public void toggleSelected() {
        selectedOption().ifPresent(this::toggle);
    }

    private void toggle(Row r) {
        if (r.replayed()) {
            status.setText(r.option().name() + ": a replayed robot's option is only shown, never switched");
            return;
        }
        SendResult result = context.switches().set(r.robotId(), r.option().name(), !r.option().wanted());
        status.setText("Switching " + r.option().name() + (r.option().wanted() ? " off" : " on") + " for robot "
                + r.robotId() + ": " + result.describe());
        rebuild = true;
    }

    /**
     * Puts the option into the robot's match digest (last place) or takes it out; sent outside
     * play only (held like every request), shown as confirmed once the robot's list says so.
     */
    private void toggleGame(Row r) {
        if (r.replayed()) {
            status.setText(r.option().name() + ": a replayed robot's option is only shown, never switched");
            return;
        }
        List<String> items = new java.util.ArrayList<>(context.switches().options().matchItems(r.robotId()));
        boolean in = items.remove(r.option().name());
        if (!in) {
            items.add(r.option().name());
        }
        SendResult result = context.switches().options().setMatchItems(r.robotId(), items);
        status.setText((in ? "Taking " + r.option().name() + " out of" : "Putting " + r.option().name() + " into")
                + " robot " + r.robotId() + "'s game digest: " + result.describe());
        rebuild = true;
    }

    /** Gives the tree the keyboard, on its selected row (the first option when none is selected). */
    private void focusTree() {
        if (tree.getScene() == null || filter.isFocused()) {
            return;
        }
        if (tree.getSelectionModel().isEmpty() && tree.getExpandedItemCount() > 1) {
            tree.getSelectionModel().select(1);
        }
        int selected = tree.getSelectionModel().getSelectedIndex();
        if (selected >= 0) {
            tree.getFocusModel().focus(selected);
        }
        tree.requestFocus();
    }

    /** Opens the visualisation registered for the selected option's data kind. */
    public void openSelected() {
        selectedOption().ifPresent(r -> {
            Optional<ViewSpec> spec = context.registry().forKind(r.option().kind());
            if (spec.isPresent()) {
                context.open(spec.get(), new ViewSource(r.robotId(), r.option().name()));
            } else {
                status.setText(r.option().name() + ": " + r.option().kindName() + " — no visualisation for it");
            }
        });
    }

    static String label(OptionState o) {
        StringBuilder s = new StringBuilder(o.name()).append("   ").append(o.kindName());
        if (o.streaming()) {
            s.append(" · streaming");
        } else if (o.wanted()) {
            s.append(o.enabledOnRobot() ? " · on, waiting for data" : " · wanted, not yet on");
        } else if (o.enabledOnRobot()) {
            s.append(" · on at robot");
        }
        if (o.matchRank() > 0 || o.matchRankOnRobot() > 0) {
            s.append(o.matchConfirmed() ? " · in the game #" + o.matchRank() + " (confirmed)"
                    : o.matchRank() == 0 ? " · out of the game asked" : " · in the game #" + o.matchRank() + " asked");
        }
        if (o.description() != null && !o.description().isEmpty()) {
            s.append("   — ").append(o.description());
        }
        return s.toString();
    }

    static String robotLabel(RobotSnapshot r, RobotOptions o) {
        String name = r.name() == null || r.name().isEmpty() ? "" : " " + r.name();
        String list = o.listReceived() ? o.options().size() + " options"
                : "requesting option list (" + o.listRequests() + " requests)";
        String held = o.lastHoldReason() == null || o.lastHoldReason().isBlank() ? "" : " · waiting: " + o.lastHoldReason();
        if (r.replayed()) {
            return "Robot " + r.id() + name + " (replay)" + " — " + o.options().size() + " options";
        }
        return "Robot " + r.id() + name + (r.online() ? "" : " (offline)") + " — " + list + held;
    }

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        long ov = context.field().options().version();
        long rv = context.field().robots().version();
        // every datagram moves the robots' version, and streaming flags age without any change:
        // both are read twice a second; a changed option list at once. The tree's nodes change
        // only when a row does.
        if (!rebuild && ov == seenOptions && frame.nowMicros() - readMicros < touchline.ui.frame.SourceBar.REREAD_MICROS) {
            return;
        }
        readMicros = frame.nowMicros();
        seenOptions = ov;
        seenRobots = rv;
        rebuild = false;
        String needle = filter.getText() == null ? "" : filter.getText().trim().toLowerCase(Locale.ROOT);
        TreeItem<Row> selected = tree.getSelectionModel().getSelectedItem();
        Row keep = selected == null ? null : selected.getValue();
        for (TreeItem<Row> r : tree.getRoot().getChildren()) {
            collapsed.put(r.getValue().robotId(), !r.isExpanded());
        }
        List<TreeItem<Row>> robots = new java.util.ArrayList<>();
        TreeItem<Row> reselect = null;
        for (RobotSnapshot r : context.field().robots().robots()) {
            RobotOptions ro = context.field().options().options(r.id(), r.origin());
            TreeItem<Row> robotItem = new TreeItem<>(new Row(r.id(), robotLabel(r, ro), null, r.replayed()));
            robotItem.setExpanded(!collapsed.getOrDefault(r.id(), false) || !needle.isEmpty());
            for (OptionState o : ro.options()) {
                if (!needle.isEmpty() && !o.name().toLowerCase(Locale.ROOT).contains(needle)) {
                    continue;
                }
                TreeItem<Row> item = new TreeItem<>(new Row(r.id(), label(o), o, r.replayed()));
                robotItem.getChildren().add(item);
                if (keep != null && keep.option() != null && keep.robotId() == r.id()
                        && keep.option().name().equals(o.name())) {
                    reselect = item;
                }
            }
            if (keep != null && keep.option() == null && keep.robotId() == r.id()) {
                reselect = robotItem;
            }
            if (needle.isEmpty() || !robotItem.getChildren().isEmpty()) {
                robots.add(robotItem);
            }
        }
        if (!sameRows(robots)) {
            tree.getRoot().getChildren().setAll(robots);
            if (reselect != null) {
                tree.getSelectionModel().select(reselect);
            }
        }
    }

    private boolean sameRows(List<TreeItem<Row>> robots) {
        List<TreeItem<Row>> old = tree.getRoot().getChildren();
        if (old.size() != robots.size()) {
            return false;
        }
        for (int i = 0; i < old.size(); i++) {
            if (!old.get(i).getValue().equals(robots.get(i).getValue())
                    || old.get(i).getChildren().size() != robots.get(i).getChildren().size()) {
                return false;
            }
            for (int k = 0; k < old.get(i).getChildren().size(); k++) {
                if (!old.get(i).getChildren().get(k).getValue().equals(robots.get(i).getChildren().get(k).getValue())) {
                    return false;
                }
            }
        }
        return true;
    }
}
