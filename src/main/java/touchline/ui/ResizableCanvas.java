package touchline.ui;

import javafx.scene.canvas.Canvas;
import javafx.scene.layout.Pane;

/**
 * A canvas that fills its pane and asks for a redraw when the pane is resized. The pane is
 * opaque: JavaFX then starts a redraw of the canvas at this pane instead of repainting every
 * background behind it (the views, tabs and splits around it) in each frame the canvas changes
 * (docs/benchmarks.md, "Twelfth session").
 */
public final class ResizableCanvas extends Pane {

    private final Canvas canvas = new Canvas(10, 10);
    private long resizes;

    public ResizableCanvas(Runnable onResize) {
        getChildren().add(canvas);
        getStyleClass().add("canvas-pane"); // opaque, one pixel beyond the pane: touchline.css
        canvas.widthProperty().bind(widthProperty());
        canvas.heightProperty().bind(heightProperty());
        widthProperty().addListener((o, a, b) -> resized(onResize));
        heightProperty().addListener((o, a, b) -> resized(onResize));
        setMinSize(50, 50);
        setPrefSize(480, 360);
    }

    private void resized(Runnable onResize) {
        resizes++;
        onResize.run();
    }

    /** How often the width or the height changed (a redraw without new data is due then). */
    public long resizes() {
        return resizes;
    }

    public Canvas canvas() {
        return canvas;
    }
}
