package touchline.ui.views;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import touchline.model.RobotSnapshot;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.FrameContext;
import touchline.ui.ResizableCanvas;
import touchline.ui.SourcedView;
import touchline.ui.ViewContext;
import touchline.ui.ViewSource;

import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * The field from above (9 m × 6 m, x towards the opponent goal) with every robot at the
 * position its keep-alive reports, its heading, ID and role; offline robots are drawn hollow.
 * When a field-objects option is chosen as source, its objects are drawn too.
 */
public final class FieldView extends SourcedView {

    static final double FIELD_LENGTH = 9000;
    static final double FIELD_WIDTH = 6000;
    static final double BORDER = 700;
    private final ResizableCanvas canvas = new ResizableCanvas(() -> dirty = true);
    private long seenRobots = -1;
    private long seenObjects = -1;
    private int drawnRobots;
    private List<Mark> drawnMarks = List.of();
    private long paints;

    public FieldView(ViewContext context, ViewSource source) {
        super(context, Set.of(Fumanoid.DebugKind.FIELD_VALUE), source);
        canvas.setId("field-canvas");
        root.setCenter(canvas);
    }

    /** Robots with a position drawn in the last frame (for tests). */
    public int drawnRobots() {
        return drawnRobots;
    }

    @Override
    public void refresh(FrameContext frame) {
        bar.refresh();
        long rv = context.console().robots().version();
        ViewSource s = bar.selected();
        Optional<Latest> objects = s.isSet() ? context.stores().latest().get(s.robotId(), s.option()) : Optional.empty();
        long ov = objects.map(Latest::version).orElse(0L);
        if (rv == seenRobots && ov == seenObjects && !dirty) {
            return;
        }
        seenRobots = rv;
        // every datagram moves the robots' version: paint only when what is drawn of them moved
        List<RobotSnapshot> robots = context.console().robots().robots();
        List<Mark> marks = marks(robots);
        if (ov == seenObjects && !dirty && marks.equals(drawnMarks)) {
            return;
        }
        if (ov != seenObjects && objects.isPresent()) {
            frame.shown(objects.get().timeMicros());
        }
        seenObjects = ov;
        dirty = false;
        drawnMarks = marks;
        paints++;
        status(paint(robots, objects.orElse(null)));
    }

    /** What the field shows of one robot; two equal lists paint the same robots. */
    private record Mark(int id, boolean hasPosition, double x, double y, double theta, boolean online, String role) { }

    private static List<Mark> marks(List<RobotSnapshot> robots) {
        List<Mark> out = new java.util.ArrayList<>(robots.size());
        for (RobotSnapshot r : robots) {
            out.add(new Mark(r.id(), r.hasPosition(), r.x(), r.y(), r.theta(), r.online(), r.role()));
        }
        return out;
    }

    /** Times the field was painted (for tests: a frame without a change paints nothing). */
    public long paints() {
        return paints;
    }

    @Override
    protected String draw(Latest latest) {
        paints++;
        return paint(context.console().robots().robots(), latest);
    }

    private String paint(List<RobotSnapshot> robots, Latest objects) {
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        double w = canvas.getWidth();
        double h = canvas.getHeight();
        g.setFill(Color.DARKGREEN);
        g.fillRect(0, 0, w, h);
        double scale = Math.min(w / (FIELD_LENGTH + 2 * BORDER), h / (FIELD_WIDTH + 2 * BORDER));
        double cx = w / 2;
        double cy = h / 2;
        // straight lines as filled rectangles: a stroke costs its whole bounding box in software
        g.setFill(Color.WHITE);
        CrispLines.outline(g, cx - FIELD_LENGTH / 2 * scale - 1, cy - FIELD_WIDTH / 2 * scale - 1,
                FIELD_LENGTH * scale + 2, FIELD_WIDTH * scale + 2, 2);
        g.fillRect(Math.round(cx) - 1, Math.round(cy - FIELD_WIDTH / 2 * scale), 2, Math.round(FIELD_WIDTH * scale));
        g.setStroke(Color.WHITE);
        g.setLineWidth(2);
        g.strokeOval(cx - 750 * scale, cy - 750 * scale, 1500 * scale, 1500 * scale);
        double goal = 2600 * scale;
        g.setFill(Color.GOLD);
        CrispLines.outline(g, cx + FIELD_LENGTH / 2 * scale - 1, cy - goal / 2 - 1, 600 * scale + 2, goal + 2, 2);
        g.setFill(Color.DODGERBLUE);
        CrispLines.outline(g, cx - FIELD_LENGTH / 2 * scale - 600 * scale - 1, cy - goal / 2 - 1, 600 * scale + 2, goal + 2, 2);
        int drawn = 0;
        int noPosition = 0;
        for (RobotSnapshot r : robots) {
            if (!r.hasPosition() || !Double.isFinite(r.x()) || !Double.isFinite(r.y())) {
                noPosition++;
                continue;
            }
            double sx = cx + r.x() * scale;
            double sy = cy - r.y() * scale;
            double th = Double.isFinite(r.theta()) ? r.theta() : 0;
            g.setFill(r.online() ? Color.LIGHTSKYBLUE : Color.TRANSPARENT);
            g.setStroke(Color.BLACK);
            g.setLineWidth(1.5);
            g.fillOval(sx - 10, sy - 10, 20, 20);
            g.strokeOval(sx - 10, sy - 10, 20, 20);
            g.setStroke(Color.BLACK);
            g.strokeLine(sx, sy, sx + Math.cos(th) * 18, sy - Math.sin(th) * 18);
            g.setFill(Color.WHITE);
            String role = r.role() == null || r.role().isEmpty() ? "" : " " + r.role();
            g.fillText(r.id() + role + (r.online() ? "" : " (offline)"), sx + 12, sy - 10);
            drawn++;
        }
        int objectCount = 0;
        if (objects != null && objects.data() instanceof Fumanoid.FieldObjects fo) {
            for (Fumanoid.RelativeObject o : fo.getObjectsList()) {
                if (!Float.isFinite(o.getX()) || !Float.isFinite(o.getY())) {
                    continue;
                }
                double sx = cx + o.getX() * scale;
                double sy = cy - o.getY() * scale;
                g.setFill(ColorClasses.color(o.getColorClass()));
                g.fillOval(sx - 5, sy - 5, 10, 10);
                g.setFill(Color.WHITE);
                g.fillText(o.getLabel(), sx + 7, sy + 4);
                objectCount++;
            }
        }
        drawnRobots = drawn;
        return drawn + " robots on the field" + (noPosition > 0 ? " · " + noPosition + " without a position" : "")
                + (objects != null ? " · " + objectCount + " objects from " + objects.option() : "");
    }
}
