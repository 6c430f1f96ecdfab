package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.layout.VBox;
import javafx.stage.FileChooser;
import javafx.stage.Window;
import touchline.ui.window.StaysMaximised;

import java.io.File;
import java.util.List;

/** Team schemas: load a team's protoc descriptor set; the list says what each load brought or refused. */
final class SchemaPane {

    private final ReplayViewModel model;
    private final ListView<String> list = new ListView<>();
    private final VBox pane;

    SchemaPane(ReplayViewModel model) {
        this.model = model;
        Label title = new Label("Team schemas");
        title.setStyle("-fx-font-weight: bold;");
        Button load = ReplayView.button("schema-load", "Load team schema…", this::choose);
        Label hint = new Label("a protoc descriptor set: protoc --include_imports --descriptor_set_out=team.desc team.proto");
        hint.setStyle("-fx-opacity: 0.7;");
        list.setId("schema-list");
        list.setPrefHeight(80);
        list.setPlaceholder(new Label("No team schema loaded: the built-in FUmanoids types decode."));
        pane = new VBox(6, title, ReplayView.row(load, hint), list);
    }

    Node node() {
        return pane;
    }

    /** Adds the lines the model gained since the last frame. */
    void show(List<String> lines) {
        if (lines.size() > list.getItems().size()) {
            list.getItems().addAll(lines.subList(list.getItems().size(), lines.size()));
        }
    }

    private void choose() {
        FileChooser chooser = new FileChooser();
        chooser.setTitle("Load team schema (protoc descriptor set)");
        chooser.getExtensionFilters().addAll(new FileChooser.ExtensionFilter("Descriptor sets", "*.desc", "*.pb"),
                new FileChooser.ExtensionFilter("All files", "*"));
        Window window = pane.getScene().getWindow();
        File f = new StaysMaximised(window).during(() -> chooser.showOpenDialog(window));
        if (f != null) {
            model.loadSchema(f.toPath());
        }
    }
}
