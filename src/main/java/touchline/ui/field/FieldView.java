package touchline.ui.field;

import touchline.ui.render.FieldDrawingPainter;
import javafx.scene.Group;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.layout.Pane;
import javafx.scene.layout.StackPane;
import javafx.scene.paint.Color;
import javafx.scene.shape.Circle;
import javafx.scene.shape.Line;
import javafx.scene.shape.Rectangle;
import javafx.scene.text.Text;
import touchline.model.FramedField;
import touchline.model.RobotSnapshot;
import touchline.transport.Origin;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.frame.FrameContext;
import touchline.ui.render.ResizableCanvas;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import touchline.ui.render.ColorClasses;
import touchline.ui.render.CrispLines;

/**
 * The field from above (9 m × 6 m, x towards the opponent goal) with every robot at the
 * position its keep-alive reports, its heading, ID and role; offline robots are drawn hollow.
 * When a field-objects option is chosen as source, its objects are drawn too.
 * <p>
 * The field and the objects are painted on a canvas, the robots are shapes over it: a robot
 * that moves repaints the few pixels around it, not the whole field (it moved with every
 * robot's status, up to 30 times a second with three robots; docs/archive/benchmarks-sessions.md, "Sixteenth
 * session").
 */
public final class FieldView extends SourcedView {

    static final double FIELD_LENGTH = 9000;
    static final double FIELD_WIDTH = 6000;
    static final double BORDER = 700;
    private final ResizableCanvas canvas = new ResizableCanvas(() -> dirty = true);
    /** The robots, over the canvas, in the canvas's coordinates. */
    private final Pane robotLayer = new Pane();
    private final Map<Integer, RobotMark> shapes = new HashMap<>();
    private long seenRobots = -1;
    private long seenObjects = -1;
    private List<Mark> drawnMarks = List.of();
    private long fieldPaints;
    /** Where the field lies on the canvas: its centre and millimetres to pixels, as last painted. */
    private double cx;
    private double cy;
    private double scale;
    private String objectsNote = "";
    /** The frame the ROS 2 robots are drawn in, and where they are in it: the view's model. */
    private final FramedField frames = new FramedField();
    private final FrameChooser chooser = new FrameChooser("field-frame", "The frame the ROS 2 robots' poses and markers "
            + "are drawn in, through each robot's TF tree; automatic: map, else the one frame the poses are in",
            frames::choose, frames::frames, () -> dirty = true);
    private touchline.proto.Drawing.FieldDrawing drawnMarkers;

    public FieldView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.FIELD_VALUE), source);
        canvas.setId("field-canvas");
        robotLayer.setId("field-robots");
        robotLayer.setMouseTransparent(true);
        Rectangle clip = new Rectangle();
        clip.widthProperty().bind(robotLayer.widthProperty());
        clip.heightProperty().bind(robotLayer.heightProperty());
        robotLayer.setClip(clip); // a robot off the field's edge stays inside the view
        root.setCenter(new StackPane(canvas, robotLayer));
        bar.add(chooser.label, chooser.choice);
    }

    /** The frame the ROS 2 robots' poses and markers are drawn in, and the field as last placed in it. */
    public FramedField frames() {
        return frames;
    }

    /** The source, and the frame when one was chosen: {@code frame=odom@1001//markers}. */
    @Override
    public String layoutState() {
        return FrameChooser.layoutState(frames.chosen(), bar.selected());
    }

    @Override
    public void restoreLayoutState(String state) {
        chooser.restore(state, bar);
    }


    @Override
    public void refresh(FrameContext frame) {
        bar.refresh();
        chooser.refresh();
        long rv = field.robots().version();
        ViewSource s = bar.selected();
        Optional<Latest> objects = s.isSet() ? stores().latest().get(s.robotId(), s.option()) : Optional.empty();
        long ov = objects.map(Latest::version).orElse(0L);
        if (rv == seenRobots && ov == seenObjects && !dirty) {
            return;
        }
        seenRobots = rv;
        // every datagram moves the robots' version: show only what moved of them
        List<RobotSnapshot> robots = field.robots().robots();
        FramedField.Picture picture = frames.place(robots, field.robots().frames(Origin.LIVE),
                field.robots().frames(Origin.REPLAY), objects.map(Latest::data).filter(
                        touchline.proto.Drawing.FieldDrawing.class::isInstance).map(touchline.proto.Drawing.FieldDrawing.class::cast)
                        .orElse(null), s.robotId(), stores().showsReplay());
        List<Mark> marks = marks(picture);
        boolean field = dirty || ov != seenObjects || !java.util.Objects.equals(picture.markers(), drawnMarkers);
        if (!field && marks.equals(drawnMarks)) {
            return;
        }
        if (ov != seenObjects && objects.isPresent()) {
            frame.shown(objects.get().timeMicros());
        }
        seenObjects = ov;
        dirty = false;
        drawnMarks = marks;
        if (field) {
            drawnMarkers = picture.markers();
            paintField(objects.orElse(null));
        }
        status(place(marks));
    }

    /** What the field shows of one robot; two equal lists show the same robots. */
    private record Mark(int id, boolean hasPosition, double x, double y, double theta, boolean online, String role) {

        boolean placeable() {
            return hasPosition && Double.isFinite(x) && Double.isFinite(y);
        }

        String label() {
            return id + (role == null || role.isEmpty() ? "" : " " + role) + (online ? "" : " (offline)");
        }
    }

    /** The robots placed in the frame, and a mark without a position for each left out. */
    private static List<Mark> marks(FramedField.Picture picture) {
        List<Mark> out = new java.util.ArrayList<>(picture.robots().size());
        for (FramedField.Placed p : picture.robots()) {
            RobotSnapshot r = p.robot();
            out.add(new Mark(r.id(), true, p.x(), p.y(), p.theta(), r.online(), r.role()));
        }
        return out;
    }

    /** Times the field itself (lines, goals, objects) was painted: a resize or new objects, not a robot moving. */
    public long fieldPaints() {
        return fieldPaints;
    }

    @Override
    protected String draw(Latest latest) {
        paintField(latest);
        return place(drawnMarks);
    }

    /** Paints the field and the chosen objects, and remembers where the field lies for the robots. */
    private void paintField(Latest objects) {
        fieldPaints++;
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        double w = canvas.getWidth();
        double h = canvas.getHeight();
        g.setFill(Color.DARKGREEN);
        g.fillRect(0, 0, w, h);
        scale = Math.min(w / (FIELD_LENGTH + 2 * BORDER), h / (FIELD_WIDTH + 2 * BORDER));
        cx = w / 2;
        cy = h / 2;
        // straight lines as filled rectangles: a stroke costs its whole bounding box in software
        g.setFill(Color.WHITE);
        CrispLines.outline(g::fillRect, cx - FIELD_LENGTH / 2 * scale - 1, cy - FIELD_WIDTH / 2 * scale - 1,
                FIELD_LENGTH * scale + 2, FIELD_WIDTH * scale + 2, 2);
        g.fillRect(Math.round(cx) - 1, Math.round(cy - FIELD_WIDTH / 2 * scale), 2, Math.round(FIELD_WIDTH * scale));
        g.setStroke(Color.WHITE);
        g.setLineWidth(2);
        g.strokeOval(cx - 750 * scale, cy - 750 * scale, 1500 * scale, 1500 * scale);
        double goal = 2600 * scale;
        g.setFill(Color.GOLD);
        CrispLines.outline(g::fillRect, cx + FIELD_LENGTH / 2 * scale - 1, cy - goal / 2 - 1, 600 * scale + 2, goal + 2, 2);
        g.setFill(Color.DODGERBLUE);
        CrispLines.outline(g::fillRect, cx - FIELD_LENGTH / 2 * scale - 600 * scale - 1, cy - goal / 2 - 1, 600 * scale + 2, goal + 2, 2);
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
        } else if (objects != null && drawnMarkers != null) {
            // a ROS 2 robot's markers, moved into the chosen frame
            objectCount = new FieldDrawingPainter().paint(g, drawnMarkers, cx, cy, scale);
        }
        objectsNote = objects != null ? " · " + objectCount + " objects from " + objects.option() : "";
    }

    /** Puts each robot's shape where the robot is; returns the status line. */
    private String place(List<Mark> marks) {
        int drawn = 0;
        int noPosition = 0;
        Set<Integer> present = new java.util.HashSet<>();
        for (Mark m : marks) {
            if (!m.placeable()) {
                noPosition++;
                continue;
            }
            present.add(m.id());
            RobotMark shape = shapes.computeIfAbsent(m.id(), id -> {
                RobotMark created = new RobotMark();
                robotLayer.getChildren().add(created);
                return created;
            });
            shape.show(m, cx + m.x() * scale, cy - m.y() * scale);
            drawn++;
        }
        shapes.entrySet().removeIf(e -> {
            if (present.contains(e.getKey())) {
                return false;
            }
            robotLayer.getChildren().remove(e.getValue());
            return true;
        });
        FramedField.Picture p = frames.picture();
        noPosition += p.withoutPosition();
        return drawn + " robots " + (p.frame().isEmpty() ? "on the field" : "in " + p.frame())
                + (noPosition > 0 ? " · " + noPosition + " without a position" : "") + p.note() + objectsNote;
    }

    /** One robot on the field: a disc (hollow when offline), its heading and its ID and role. */
    private static final class RobotMark extends Group {

        private final Circle body = new Circle(10);
        private final Line heading = new Line();
        private final Text label = new Text();

        RobotMark() {
            setManaged(false);
            body.setStroke(Color.BLACK);
            body.setStrokeWidth(1.5);
            heading.setStroke(Color.BLACK);
            heading.setStrokeWidth(1.5);
            label.setFill(Color.WHITE);
            label.setX(12);
            label.setY(-10);
            getChildren().addAll(body, heading, label);
        }

        void show(Mark m, double x, double y) {
            double th = Double.isFinite(m.theta()) ? m.theta() : 0;
            setLayoutX(x);
            setLayoutY(y);
            body.setFill(m.online() ? Color.LIGHTSKYBLUE : Color.TRANSPARENT);
            heading.setEndX(Math.cos(th) * 18);
            heading.setEndY(-Math.sin(th) * 18);
            if (!m.label().equals(label.getText())) {
                label.setText(m.label());
            }
        }
    }
}
