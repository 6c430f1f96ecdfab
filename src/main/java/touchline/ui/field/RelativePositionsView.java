package touchline.ui.field;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import touchline.app.bridges.RosBridges;
import touchline.model.FramedField;
import touchline.model.RobotCentred;
import touchline.model.store.Latest;
import touchline.proto.Drawing;
import touchline.proto.Fumanoid;
import touchline.transport.Origin;
import touchline.ui.frame.FrameContext;
import touchline.ui.render.FieldDrawingPainter;
import touchline.ui.render.ResizableCanvas;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import touchline.ui.render.ColorClasses;
import touchline.ui.render.CrispLines;

/**
 * Objects around the robot, robot-centred: the robot at the middle looking up (x forward,
 * y left), rings every metre, each object a dot in its colour class with its label. The
 * scale fits the farthest object; non-finite positions are counted, not drawn.
 * <p>
 * A ROS 2 robot's source (its markers' topic) shows its markers and the other robots in the robot's
 * own frame chosen in the view ({@code base_link} by default), through its TF tree ({@link RobotCentred});
 * what has no path there is counted with the reason on the status line.
 */
public final class RelativePositionsView extends SourcedView {

    private final ResizableCanvas canvas = new ResizableCanvas(() -> dirty = true);
    /** A ROS 2 robot's surroundings in its frame chosen here: the view's model. */
    private final RobotCentred centred = new RobotCentred();
    private final FrameChooser chooser = new FrameChooser("relative-frame", "The ROS 2 robot's own frame its markers and "
            + "the other robots are drawn in, through its TF tree; automatic: base_link", centred::choose,
            centred::frames, () -> dirty = true);
    private ViewSource drawnRos = ViewSource.NONE;
    private long seenRobots = -1;
    private long seenMarkers = -1;
    private Around drawnAround;

    public RelativePositionsView(ViewContext context, ViewSource source) {
        // a ROS 2 robot's markers are field drawings: its topics of those are its sources here
        super(context.field(), Set.of(Fumanoid.DebugKind.RELATIVE_POSITIONS_VALUE), Set.of(Fumanoid.DebugKind.FIELD_VALUE),
                source);
        canvas.setId("relative-canvas");
        root.setCenter(canvas);
        bar.add(chooser.label, chooser.choice);
    }

    /** The ROS 2 robot's frame chosen, and its surroundings as last placed in it. */
    public RobotCentred centred() {
        return centred;
    }

    /** The source, and the frame when one was chosen: {@code frame=camera@1001//markers}. */
    @Override
    public String layoutState() {
        return FrameChooser.layoutState(centred.chosen(), bar.selected());
    }

    @Override
    public void restoreLayoutState(String state) {
        chooser.restore(state, bar);
    }

    @Override
    public void refresh(FrameContext frame) {
        bar.refresh();
        ViewSource s = bar.selected();
        boolean ros = s.isSet() && s.robotId() >= RosBridges.FIRST_ROBOT;
        chooser.label.setVisible(ros);
        chooser.label.setManaged(ros);
        chooser.choice.setVisible(ros);
        chooser.choice.setManaged(ros);
        if (!ros) {
            drawnRos = ViewSource.NONE;
            super.refresh(frame);
            return;
        }
        chooser.refresh();
        long rv = field.robots().version();
        Optional<Latest> markers = stores().latest().get(s.robotId(), s.option());
        long mv = markers.map(Latest::version).orElse(0L);
        if (s.equals(drawnRos) && rv == seenRobots && mv == seenMarkers && !dirty) {
            return;
        }
        boolean forced = dirty || !s.equals(drawnRos);
        drawnRos = s;
        seenRobots = rv;
        dirty = false;
        Origin origin = stores().showsReplay() ? Origin.REPLAY : Origin.LIVE;
        FramedField.Picture p = centred.place(s.robotId(), origin, field.robots().robots(), field.robots().frames(origin),
                markers.map(Latest::data).filter(Drawing.FieldDrawing.class::isInstance)
                        .map(Drawing.FieldDrawing.class::cast).orElse(null));
        if (mv != seenMarkers && markers.isPresent()) {
            frame.shown(markers.get().timeMicros());
        }
        seenMarkers = mv;
        Around around = Around.of(p);
        // every datagram moves the robots' version: paint only what changed on screen
        if (forced || !around.equals(drawnAround)) {
            drawnAround = around;
            status(paint(around, p) + (markers.isEmpty() ? " · no markers yet on " + s.option() : ""));
        }
    }

    /** One robot drawn around the ROS 2 robot: millimetres and radians in its frame. */
    private record Dot(String label, double x, double y, double theta, boolean online) { }

    /** What the view shows of a ROS 2 robot's surroundings; two equal ones look the same. */
    private record Around(String frame, List<Dot> robots, Drawing.FieldDrawing markers, String note) {

        static Around of(FramedField.Picture p) {
            List<Dot> dots = new ArrayList<>(p.robots().size());
            for (FramedField.Placed r : p.robots()) {
                dots.add(new Dot(r.robot().id() + " " + r.robot().label(), r.x(), r.y(), r.theta(), r.robot().online()));
            }
            return new Around(p.frame(), dots, p.markers(), p.note());
        }
    }

    /** Paints the robots and markers around the ROS 2 robot; returns the status line. */
    private String paint(Around a, FramedField.Picture p) {
        double range = 1000;
        for (Dot d : a.robots()) {
            range = Math.max(range, Math.hypot(d.x(), d.y()) * 1.15);
        }
        Drawing.FieldDrawing upright = null;
        if (a.markers() != null) {
            // the painter draws x right and y up: x forward is screen up, y left is screen left
            Drawing.FieldDrawing.Builder b = a.markers().toBuilder().clearShapes();
            for (Drawing.FieldShape s : a.markers().getShapesList()) {
                Drawing.FieldShape.Builder t = s.toBuilder().clearXy();
                for (int i = 0; i + 1 < s.getXyCount(); i += 2) {
                    t.addXy(-s.getXy(i + 1)).addXy(s.getXy(i));
                    range = Math.max(range, Math.hypot(s.getXy(i), s.getXy(i + 1)) * 1.15);
                }
                b.addShapes(t);
            }
            upright = b.build();
        }
        double scale = around(range);
        double cx = canvas.getWidth() / 2;
        double cy = canvas.getHeight() / 2;
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        int shapes = upright == null ? 0 : new FieldDrawingPainter().paint(g, upright, cx, cy, scale);
        g.setLineWidth(1.5);
        for (Dot d : a.robots()) {
            double sx = cx - d.y() * scale;
            double sy = cy - d.x() * scale;
            double th = Double.isFinite(d.theta()) ? d.theta() : 0;
            g.setFill(d.online() ? Color.LIGHTSKYBLUE : Color.TRANSPARENT);
            g.fillOval(sx - 8, sy - 8, 16, 16);
            g.setStroke(Color.LIGHTSKYBLUE);
            g.strokeOval(sx - 8, sy - 8, 16, 16);
            g.strokeLine(sx, sy, sx - Math.sin(th) * 16, sy - Math.cos(th) * 16);
            g.setFill(Color.WHITE);
            g.fillText(d.label() + String.format(" (%.0f, %.0f)", d.x(), d.y()), sx + 10, sy + 4);
        }
        self();
        int noPosition = p.withoutPosition();
        return a.robots().size() + " robots in " + a.frame() + (noPosition > 0 ? " · " + noPosition + " without a position" : "")
                + (a.markers() == null ? "" : " · " + shapes + " markers") + a.note();
    }

    /** Paints the background and the rings every metre up to {@code range} millimetres; returns pixels per millimetre. */
    private double around(double range) {
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        double w = canvas.getWidth();
        double h = canvas.getHeight();
        g.setFill(Color.gray(0.12));
        g.fillRect(0, 0, w, h);
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
        return scale;
    }

    /** Paints the robot itself at the middle, looking up, over what lies around it. */
    private void self() {
        double cx = canvas.getWidth() / 2;
        double cy = canvas.getHeight() / 2;
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        g.setFill(Color.LIGHTSKYBLUE);
        g.fillPolygon(new double[] {cx, cx - 8, cx + 8}, new double[] {cy - 14, cy + 8, cy + 8}, 3);
    }

    @Override
    protected String draw(Latest latest) {
        if (!(latest.data() instanceof Fumanoid.RelativePositions p)) {
            return "not relative positions: " + latest.kind();
        }
        double range = 1000;
        int bad = 0;
        for (Fumanoid.RelativeObject o : p.getObjectsList()) {
            if (Float.isFinite(o.getX()) && Float.isFinite(o.getY())) {
                range = Math.max(range, Math.hypot(o.getX(), o.getY()) * 1.15);
            }
        }
        double scale = around(range);
        self();
        double cx = canvas.getWidth() / 2;
        double cy = canvas.getHeight() / 2;
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
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
