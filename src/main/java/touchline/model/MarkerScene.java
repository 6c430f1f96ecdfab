package touchline.model;

import touchline.proto.Drawing;
import touchline.protocol.ros2.RosMessage;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What one topic's {@code visualization_msgs/msg/MarkerArray} messages have drawn so far, in 2D
 * on the field: markers are kept by namespace and id until a DELETE of theirs or a DELETEALL
 * (any namespace), as RViz keeps them. SPHERE and CYLINDER are circles, POINTS and
 * SPHERE_LIST dots, LINE_STRIP and LINE_LIST lines, TEXT_VIEW_FACING text; the other types
 * (arrows, cubes, meshes) are counted as not drawn. Positions are in the marker's frame (kept with
 * the shape: the field view moves it into the frame chosen there), metres in ROS and millimetres on
 * the field, moved and turned by the marker's pose; lifetimes
 * are not aged out. Bounded: at most {@link #MAX_MARKERS} markers and
 * {@link #MAX_POINTS} points per marker. Not thread-safe: one writer.
 */
public final class MarkerScene {

    public static final int MAX_MARKERS = 2000;
    public static final int MAX_POINTS = 4096;

    private record Id(String ns, int id) { }

    private final Map<Id, Drawing.FieldShape> shapes = new LinkedHashMap<>();
    private long dropped;

    /** Applies one MarkerArray (or a lone Marker). */
    public void apply(RosMessage m) {
        if (m.typeName().endsWith("Marker")) {
            mark(m);
            return;
        }
        if (m.get("markers") instanceof RosMessage[] markers) {
            for (RosMessage marker : markers) {
                mark(marker);
            }
        }
    }

    private void mark(RosMessage m) {
        int action = (int) m.number("action");
        Id id = new Id(String.valueOf(m.get("ns")), (int) m.number("id"));
        if (action == 3) {
            shapes.clear();
            return;
        }
        if (action == 2) {
            shapes.remove(id);
            return;
        }
        Drawing.FieldShape shape = shape(m);
        if (shape == null || (!shapes.containsKey(id) && shapes.size() >= MAX_MARKERS)) {
            dropped++;
            shapes.remove(id);
            return;
        }
        shapes.put(id, shape);
    }

    /** One marker as a shape on the field, or null for a type not drawn in 2D. */
    static Drawing.FieldShape shape(RosMessage m) {
        Drawing.FieldShape.Builder s = Drawing.FieldShape.newBuilder().setArgb(argb(m))
                .setFrame(RosReadings.frameId(m.at("header.frame_id")));
        double px = m.number("pose.position.x");
        double py = m.number("pose.position.y");
        double qz = m.number("pose.orientation.z");
        double qw = m.number("pose.orientation.w");
        double yaw = Double.isFinite(qz) && Double.isFinite(qw) && (qz != 0 || qw != 0) ? 2 * Math.atan2(qz, qw) : 0;
        double scale = m.number("scale.x");
        switch ((int) m.number("type")) {
            case 2, 3 -> s.setForm(Drawing.FieldShape.Form.CIRCLE).setSize(mm(scale / 2)).addXy(mm(px)).addXy(mm(py));
            case 9 -> s.setForm(Drawing.FieldShape.Form.TEXT).setText(String.valueOf(m.get("text")))
                    .setSize(mm(m.number("scale.z"))).addXy(mm(px)).addXy(mm(py));
            case 7, 8 -> points(s.setForm(Drawing.FieldShape.Form.DOT).setSize(mm(scale)), m, px, py, yaw);
            case 4, 5 -> points(s.setForm(Drawing.FieldShape.Form.POLYLINE).setSize(mm(scale))
                    .setSegments((int) m.number("type") == 5), m, px, py, yaw);
            default -> {
                return null;
            }
        }
        return s.getXyCount() >= 2 && allFinite(s.getXyList()) ? s.build() : null;
    }

    private static void points(Drawing.FieldShape.Builder s, RosMessage m, double px, double py, double yaw) {
        RosMessage[] points = m.get("points") instanceof RosMessage[] p ? p : new RosMessage[0];
        double c = Math.cos(yaw);
        double sn = Math.sin(yaw);
        for (int i = 0; i < Math.min(points.length, MAX_POINTS); i++) {
            double x = points[i].number("x");
            double y = points[i].number("y");
            s.addXy(mm(px + c * x - sn * y)).addXy(mm(py + sn * x + c * y));
        }
    }

    private static boolean allFinite(List<Float> values) {
        for (float v : values) {
            if (!Float.isFinite(v)) {
                return false;
            }
        }
        return true;
    }

    private static float mm(double metres) {
        return (float) (metres * 1000);
    }

    private static int argb(RosMessage m) {
        double a = m.number("color.a");
        return channel(Double.isNaN(a) || a == 0 ? 1 : a) << 24 | channel(m.number("color.r")) << 16
                | channel(m.number("color.g")) << 8 | channel(m.number("color.b"));
    }

    private static int channel(double v) {
        return Double.isFinite(v) ? (int) Math.round(Math.max(0, Math.min(1, v)) * 255) : 255;
    }

    /** The scene as it stands, named {@code option} (the topic). */
    public Drawing.FieldDrawing drawing(String option) {
        return Drawing.FieldDrawing.newBuilder().setOption(option).addAllShapes(new ArrayList<>(shapes.values()))
                .setDropped((int) Math.min(Integer.MAX_VALUE, dropped)).build();
    }
}
