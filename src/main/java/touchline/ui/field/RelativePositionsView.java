package touchline.ui.field;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.render.ResizableCanvas;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.Set;
import touchline.ui.render.ColorClasses;
import touchline.ui.render.CrispLines;

/**
 * Objects around the robot, robot-centred: the robot at the middle looking up (x forward,
 * y left), rings every metre, each object a dot in its colour class with its label. The
 * scale fits the farthest object; non-finite positions are counted, not drawn.
 */
public final class RelativePositionsView extends SourcedView {

    private final ResizableCanvas canvas = new ResizableCanvas(() -> dirty = true);

    public RelativePositionsView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.RELATIVE_POSITIONS_VALUE), source);
        canvas.setId("relative-canvas");
        root.setCenter(canvas);
    }

    @Override
    protected String draw(Latest latest) {
        if (!(latest.data() instanceof Fumanoid.RelativePositions p)) {
            return "not relative positions: " + latest.kind();
        }
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        double w = canvas.getWidth();
        double h = canvas.getHeight();
        g.setFill(Color.gray(0.12));
        g.fillRect(0, 0, w, h);
        double range = 1000;
        int bad = 0;
        for (Fumanoid.RelativeObject o : p.getObjectsList()) {
            if (Float.isFinite(o.getX()) && Float.isFinite(o.getY())) {
                range = Math.max(range, Math.hypot(o.getX(), o.getY()) * 1.15);
            }
        }
        double cx = w / 2;
        double cy = h / 2;
        double scale = Math.min(w, h) / 2 / range;
        g.setStroke(Color.gray(0.45));
        g.setLineWidth(1);
        g.setFill(Color.gray(0.6));
        for (int m = 1; m * 1000 <= range; m++) {
            double r = m * 1000 * scale;
            g.strokeOval(cx - r, cy - r, 2 * r, 2 * r);
            g.fillText(m + " m", cx + r + 2, cy - 2);
        }
        g.setFill(Color.gray(0.45));
        CrispLines.vertical(g::fillRect, cx, 0, h);
        CrispLines.horizontal(g::fillRect, 0, w, cy);
        g.setFill(Color.LIGHTSKYBLUE);
        g.fillPolygon(new double[] {cx, cx - 8, cx + 8}, new double[] {cy - 14, cy + 8, cy + 8}, 3);
        for (Fumanoid.RelativeObject o : p.getObjectsList()) {
            if (!Float.isFinite(o.getX()) || !Float.isFinite(o.getY())) {
                bad++;
                continue;
            }
            // x forward is screen up, y left is screen left
            double sx = cx - o.getY() * scale;
            double sy = cy - o.getX() * scale;
            g.setFill(ColorClasses.color(o.getColorClass()));
            g.fillOval(sx - 6, sy - 6, 12, 12);
            g.setFill(Color.WHITE);
            g.fillText(o.getLabel() + String.format(" (%.0f, %.0f)", o.getX(), o.getY()), sx + 8, sy + 4);
        }
        return p.getObjectsCount() + " objects" + (bad > 0 ? " · " + bad + " with invalid position not drawn" : "");
    }
}
