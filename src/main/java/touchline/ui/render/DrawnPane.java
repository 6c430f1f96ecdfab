package touchline.ui.render;

import javafx.scene.layout.Pane;

/**
 * A pane a view draws into itself (a canvas, its own pixels): it tells the view when it changed
 * size, since a redraw without new data is due then. The pane is opaque: JavaFX then starts a
 * redraw of what is drawn at this pane instead of repainting every background behind it (the
 * views, tabs and splits around it) in each frame it changes (docs/archive/benchmarks-sessions.md, "Twelfth
 * session").
 */
public abstract class DrawnPane extends Pane {

    protected DrawnPane(Runnable onResize) {
        getStyleClass().add("canvas-pane"); // opaque, one pixel beyond the pane: touchline.css
        widthProperty().addListener((o, a, b) -> onResize.run());
        heightProperty().addListener((o, a, b) -> onResize.run());
        setMinSize(50, 50);
        setPrefSize(480, 360);
    }
}
