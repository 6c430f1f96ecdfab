package touchline.ui.render;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import touchline.proto.Drawing;

/**
 * Paints a ROS 2 robot's markers ({@link touchline.model.MarkerScene}) on the field view's
 * canvas: dots, lines, circles and text in their colours, field millimetres to pixels as the
 * field is painted ({@code cx, cy} its centre, {@code scale} pixels per millimetre).
 */
public final class FieldDrawingPainter {

    /** Paints {@code d}; returns how many shapes it drew. */
    public int paint(GraphicsContext g, Drawing.FieldDrawing d, double cx, double cy, double scale) {
        for (Drawing.FieldShape s : d.getShapesList()) {
            int argb = s.getArgb();
            Color c = Color.rgb(argb >> 16 & 0xFF, argb >> 8 & 0xFF, argb & 0xFF, (argb >>> 24) / 255.0);
            g.setFill(c);
            g.setStroke(c);
            double x = cx + s.getXy(0) * scale;
            double y = cy - s.getXy(1) * scale;
            switch (s.getForm()) {
                case CIRCLE -> {
                    double r = Math.max(2, s.getSize() * scale);
                    g.setLineWidth(2);
                    g.strokeOval(x - r, y - r, 2 * r, 2 * r);
                }
                case TEXT -> g.fillText(s.getText(), x, y);
                case DOT -> {
                    double r = Math.max(2, s.getSize() * scale / 2);
                    for (int i = 0; i + 1 < s.getXyCount(); i += 2) {
                        g.fillOval(cx + s.getXy(i) * scale - r, cy - s.getXy(i + 1) * scale - r, 2 * r, 2 * r);
                    }
                }
                case POLYLINE -> {
                    g.setLineWidth(Math.max(1, s.getSize() * scale));
                    int step = s.getSegments() ? 4 : 2;
                    for (int i = 0; i + 3 < s.getXyCount(); i += step) {
                        g.strokeLine(cx + s.getXy(i) * scale, cy - s.getXy(i + 1) * scale,
                                cx + s.getXy(i + 2) * scale, cy - s.getXy(i + 3) * scale);
                    }
                }
            }
        }
        return d.getShapesCount();
    }
}
