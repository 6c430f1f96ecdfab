package touchline.ui;

import javafx.scene.canvas.Canvas;
import javafx.scene.layout.Pane;

/** A canvas that fills its pane and asks for a redraw when the pane is resized. */
public final class ResizableCanvas extends Pane {

    private final Canvas canvas = new Canvas(10, 10);

    public ResizableCanvas(Runnable onResize) {
        getChildren().add(canvas);
        canvas.widthProperty().bind(widthProperty());
        canvas.heightProperty().bind(heightProperty());
        widthProperty().addListener((o, a, b) -> onResize.run());
        heightProperty().addListener((o, a, b) -> onResize.run());
        setMinSize(50, 50);
        setPrefSize(480, 360);
    }

    public Canvas canvas() {
        return canvas;
    }
}
