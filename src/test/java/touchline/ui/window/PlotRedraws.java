package touchline.ui.window;

import javafx.scene.Node;
import javafx.scene.image.ImageView;
import javafx.scene.layout.Region;

/**
 * Counts, from now on, how often a plot put a new picture on screen and how often its pane changed
 * size, by watching what the window shows: the plot's picture is one image that each redraw
 * replaces (its two buffers take turns), so every redraw changes the image shown. FX thread.
 */
final class PlotRedraws {

    private long draws;
    private long resizes;

    /** @param plot a plot view's node (its canvas is {@code #plot-canvas}) */
    PlotRedraws(Node plot) {
        Region canvas = (Region) plot.lookup("#plot-canvas");
        ImageView picture = (ImageView) canvas.getChildrenUnmodifiable().stream().filter(ImageView.class::isInstance)
                .findFirst().orElseThrow();
        picture.imageProperty().addListener((o, a, b) -> draws++);
        canvas.widthProperty().addListener((o, a, b) -> resizes++);
        canvas.heightProperty().addListener((o, a, b) -> resizes++);
    }

    long draws() {
        return draws;
    }

    long resizes() {
        return resizes;
    }
}
