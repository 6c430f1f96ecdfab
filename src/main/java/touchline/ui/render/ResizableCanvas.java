package touchline.ui.render;

import javafx.scene.canvas.Canvas;

/** A canvas that fills its {@link DrawnPane}. */
public final class ResizableCanvas extends DrawnPane {

    private final Canvas canvas = new Canvas(10, 10);

    public ResizableCanvas(Runnable onResize) {
        super(onResize);
        getChildren().add(canvas);
        canvas.widthProperty().bind(widthProperty());
        canvas.heightProperty().bind(heightProperty());
    }

    public Canvas canvas() {
        return canvas;
    }
}
