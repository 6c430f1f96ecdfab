package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.proto.Drawing;
import touchline.protocol.ros2.RosMessage;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** MarkerArrays to shapes on the field, kept by namespace and id; DELETE and DELETEALL honoured. */
class MarkerSceneTest {

    private static RosMessage msg(String type, String[] names, Object... values) {
        return new RosMessage(type, null, names, values);
    }

    private static RosMessage xyz(double x, double y) {
        return msg("geometry_msgs/msg/Point", new String[] {"x", "y", "z"}, x, y, 0.0);
    }

    /** A marker at (x, y) metres turned by yaw, scale s, orange. */
    private static RosMessage marker(String ns, int id, int type, int action, double x, double y, double yaw, double s,
                                     String text, RosMessage... points) {
        RosMessage pose = msg("geometry_msgs/msg/Pose", new String[] {"position", "orientation"}, xyz(x, y),
                msg("geometry_msgs/msg/Quaternion", new String[] {"x", "y", "z", "w"}, 0.0, 0.0, Math.sin(yaw / 2), Math.cos(yaw / 2)));
        return msg("visualization_msgs/msg/Marker",
                new String[] {"ns", "id", "type", "action", "pose", "scale", "color", "points", "text"},
                ns, id, type, action, pose,
                msg("geometry_msgs/msg/Vector3", new String[] {"x", "y", "z"}, s, s, 0.25),
                msg("std_msgs/msg/ColorRGBA", new String[] {"r", "g", "b", "a"}, 1.0f, 0.5f, 0.0f, 1.0f),
                points, text);
    }

    private static RosMessage array(RosMessage... markers) {
        return msg("visualization_msgs/msg/MarkerArray", new String[] {"markers"}, (Object) markers);
    }

    private static List<Float> xy(Drawing.FieldShape s) {
        return s.getXyList().stream().map(v -> (float) Math.round(v)).toList();
    }

    @Test
    void spheresCylindersPointsLinesAndTextBecomeShapesInFieldMillimetres() {
        MarkerScene scene = new MarkerScene();
        scene.apply(array(
                marker("ball", 0, 2, 0, 1.5, -0.5, 0, 0.1, ""),
                marker("kick", 1, 3, 0, 1.0, 0.0, 0, 0.6, ""),
                marker("seen", 2, 8, 0, 0, 0, 0, 0.05, "", xyz(1, 2), xyz(-1, 0)),
                marker("path", 3, 4, 0, 1.0, 0.0, Math.PI / 2, 0.02, "", xyz(0, 0), xyz(1, 0), xyz(1, 1)),
                marker("lines", 4, 5, 0, 0, 0, 0, 0.02, "", xyz(0, 0), xyz(1, 0), xyz(2, 0), xyz(2, 1)),
                marker("say", 5, 9, 0, 0.5, 0.25, 0, 0.1, "go to ball"),
                marker("box", 6, 1, 0, 0, 0, 0, 0.1, "")));
        Drawing.FieldDrawing d = scene.drawing("/markers");
        assertEquals("/markers", d.getOption());
        assertEquals(6, d.getShapesCount(), "the cube is not drawn");
        assertEquals(1, d.getDropped());

        Drawing.FieldShape ball = d.getShapes(0);
        assertEquals(Drawing.FieldShape.Form.CIRCLE, ball.getForm());
        assertEquals(List.of(1500f, -500f), xy(ball));
        assertEquals(50f, ball.getSize(), 1e-3, "radius: half the diameter");
        assertEquals(0xFFFF8000, ball.getArgb());
        assertEquals(300f, d.getShapes(1).getSize(), 1e-3);
        assertEquals(Drawing.FieldShape.Form.DOT, d.getShapes(2).getForm());
        assertEquals(List.of(1000f, 2000f, -1000f, 0f), xy(d.getShapes(2)));
        Drawing.FieldShape path = d.getShapes(3);
        assertEquals(Drawing.FieldShape.Form.POLYLINE, path.getForm());
        assertFalse(path.getSegments());
        // turned a quarter left about its pose at (1, 0): (1, 0) → (1, 1), (1, 1) → (0, 1)
        assertEquals(List.of(1000f, 0f, 1000f, 1000f, 0f, 1000f), xy(path));
        assertTrue(d.getShapes(4).getSegments());
        assertEquals(Drawing.FieldShape.Form.TEXT, d.getShapes(5).getForm());
        assertEquals("go to ball", d.getShapes(5).getText());
        assertEquals(List.of(500f, 250f), xy(d.getShapes(5)));
    }

    @Test
    void aMarkerIsReplacedByItsNamespaceAndIdDeletedByDeleteAndAllGoByDeleteAll() {
        MarkerScene scene = new MarkerScene();
        scene.apply(array(marker("ball", 0, 2, 0, 1, 1, 0, 0.1, ""), marker("ball", 1, 2, 0, 2, 2, 0, 0.1, ""),
                marker("other", 0, 2, 0, 3, 3, 0, 0.1, "")));
        assertEquals(3, scene.drawing("/m").getShapesCount());
        scene.apply(array(marker("ball", 0, 2, 0, -1, -1, 0, 0.1, "")));
        assertEquals(List.of(-1000f, -1000f), xy(scene.drawing("/m").getShapes(0)), "moved, not added");
        assertEquals(3, scene.drawing("/m").getShapesCount());
        scene.apply(array(marker("ball", 1, 0, 2, 0, 0, 0, 0, "")));
        assertEquals(2, scene.drawing("/m").getShapesCount(), "ball 1 deleted");
        assertEquals(List.of(3000f, 3000f), xy(scene.drawing("/m").getShapes(1)));
        scene.apply(array(marker("", 0, 0, 3, 0, 0, 0, 0, ""), marker("ball", 7, 2, 0, 0.5, 0, 0, 0.1, "")));
        Drawing.FieldDrawing after = scene.drawing("/m");
        assertEquals(1, after.getShapesCount(), "DELETEALL clears what came before it, not what follows");
        assertEquals(List.of(500f, 0f), xy(after.getShapes(0)));
    }

    @Test
    void aSceneIsBounded() {
        MarkerScene scene = new MarkerScene();
        RosMessage[] many = new RosMessage[MarkerScene.MAX_MARKERS + 5];
        for (int i = 0; i < many.length; i++) {
            many[i] = marker("n", i, 2, 0, 0, 0, 0, 0.1, "");
        }
        scene.apply(array(many));
        assertEquals(MarkerScene.MAX_MARKERS, scene.drawing("/m").getShapesCount());
        assertEquals(5, scene.drawing("/m").getDropped());
    }

    @Test
    void aScenePerRobotAndTopicIsTheFieldViewsData() {
        RosDebugData data = new RosDebugData();
        data.of(1001, "/markers", array(marker("ball", 0, 2, 0, 1, 1, 0, 0.1, "")));
        RosDebugData.Data second = data.of(1001, "/markers", array(marker("ball", 1, 2, 0, 2, 2, 0, 0.1, ""))).orElseThrow();
        assertEquals(touchline.proto.Fumanoid.DebugKind.FIELD_VALUE, second.debugKind());
        assertEquals(2, ((Drawing.FieldDrawing) second.data()).getShapesCount());
        RosDebugData.Data otherRobot = data.of(1002, "/markers", array(marker("ball", 1, 2, 0, 2, 2, 0, 0.1, ""))).orElseThrow();
        assertEquals(1, ((Drawing.FieldDrawing) otherRobot.data()).getShapesCount());
    }

    @Test
    void aMarkerKeepsItsFrameForTheFieldViewToMoveItThere() {
        RosMessage inBase = msg("visualization_msgs/msg/Marker", new String[] {"header", "ns", "id", "type", "action", "pose",
                "scale"}, msg("std_msgs/msg/Header", new String[] {"frame_id"}, "/base_link"), "ball", 0, 2, 0,
                msg("geometry_msgs/msg/Pose", new String[] {"position"}, xyz(1, 0)),
                msg("geometry_msgs/msg/Vector3", new String[] {"x", "y", "z"}, 0.1, 0.1, 0.1));
        MarkerScene scene = new MarkerScene();
        scene.apply(array(inBase, marker("say", 1, 9, 0, 0, 0, 0, 0.1, "hi")));
        assertEquals("base_link", scene.drawing("/m").getShapes(0).getFrame(), "without ROS 1's slash");
        assertEquals("", scene.drawing("/m").getShapes(1).getFrame(), "none given");
    }
}
