package touchline.ui.window;

import javafx.collections.FXCollections;
import javafx.scene.Scene;
import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import javafx.scene.input.KeyCode;
import javafx.scene.layout.VBox;
import javafx.stage.Modality;
import javafx.stage.Stage;
import javafx.stage.StageStyle;
import javafx.stage.Window;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import touchline.ui.frame.ViewSource;

/**
 * Ctrl+K: type a few letters, Enter opens. Lists every registered view and, for every robot's
 * debug option, its visualisation.
 */
public final class QuickOpen {

    /** One line of the list and what it opens. */
    public record Choice(String label, ViewSpec spec, ViewSource source) {
        @Override
        public String toString() {
            return label;
        }
    }

    private final ViewContext context;
    private final WindowPlaces places;
    private final java.util.function.BiConsumer<ViewSpec, ViewSource> opener;

    public QuickOpen(ViewContext context, WindowPlaces places) {
        this(context, places, context::open);
    }

    /** @param opener what Enter does with the chosen view (the console window's: open it and move the keyboard into it) */
    public QuickOpen(ViewContext context, WindowPlaces places, java.util.function.BiConsumer<ViewSpec, ViewSource> opener) {
        this.context = context;
        this.places = places;
        this.opener = opener;
    }

    public List<Choice> choices() {
        List<Choice> out = new ArrayList<>();
        for (ViewSpec s : context.registry().all()) {
            if (!s.id().equals(ViewRegistry.RAW)) {
                out.add(new Choice(s.title() + " — " + s.help(), s, ViewSource.NONE));
            }
        }
        for (RobotSnapshot r : context.field().robots().robots()) {
            String robot = "robot " + r.id() + (r.replayed() ? " (replay)" : "");
            for (OptionState o : context.field().options().options(r.id(), r.origin()).options()) {
                context.registry().forKind(o.kind()).ifPresent(spec -> out.add(new Choice(
                        spec.title() + ": " + robot + " · " + o.name(), spec, new ViewSource(r.id(), o.name()))));
            }
        }
        return out;
    }

    /**
     * The choices whose label holds {@code text} (any case), those whose title holds it first: a
     * view named by what was typed ranks above one whose help text merely mentions it.
     */
    public List<Choice> matching(String text) {
        String n = text.toLowerCase(Locale.ROOT);
        return choices().stream().filter(c -> c.label().toLowerCase(Locale.ROOT).contains(n))
                .sorted(java.util.Comparator.comparingInt(c -> rank(c, n))).toList(); // stable: registry order within a rank
    }

    /** 0: the title starts with it; 1: the title holds it; 2: only the help text does. */
    private static int rank(Choice c, String n) {
        int help = c.label().indexOf(" — ");
        String title = (help < 0 ? c.label() : c.label().substring(0, help)).toLowerCase(Locale.ROOT);
        return title.startsWith(n) ? 0 : title.contains(n) ? 1 : 2;
    }

    public Stage show(Window owner) {
        Stage stage = new Stage(StageStyle.UTILITY);
        stage.initOwner(owner);
        stage.initModality(Modality.WINDOW_MODAL);
        stage.setTitle("Open view");
        TextField filter = new TextField();
        filter.setId("quick-open-filter");
        filter.setPromptText("type to find a view or option, Enter opens");
        javafx.collections.ObservableList<Choice> items = FXCollections.observableArrayList(choices());
        ListView<Choice> list = new ListView<>(items);
        list.setId("quick-open-list");
        list.getSelectionModel().select(0);
        filter.textProperty().addListener((o, a, b) -> {
            items.setAll(matching(b));
            list.getSelectionModel().select(0);
        });
        CloseAfterKey closer = new CloseAfterKey(stage);
        Runnable go = () -> {
            Choice c = list.getSelectionModel().getSelectedItem();
            if (c != null) {
                closer.close(() -> opener.accept(c.spec(), c.source()));
            }
        };
        filter.setOnAction(e -> go.run());
        filter.addEventFilter(javafx.scene.input.KeyEvent.KEY_PRESSED, e -> {
            if (e.getCode() == KeyCode.ESCAPE) {
                closer.close();
                e.consume();
            } else if (e.getCode() == KeyCode.DOWN) {
                list.getSelectionModel().selectNext();
                e.consume();
            } else if (e.getCode() == KeyCode.UP) {
                list.getSelectionModel().selectPrevious();
                e.consume();
            }
        });
        list.setOnMouseClicked(e -> {
            if (e.getClickCount() == 2) {
                go.run();
            }
        });
        VBox.setVgrow(list, javafx.scene.layout.Priority.ALWAYS);
        Scene scene = new Scene(new VBox(6, filter, list));
        if (owner != null && owner.getScene() != null) {
            scene.getStylesheets().addAll(owner.getScene().getStylesheets());
        }
        stage.setScene(scene);
        places.keep(stage, "quick-open", 640, 400);
        stage.show();
        filter.requestFocus();
        return stage;
    }
}
