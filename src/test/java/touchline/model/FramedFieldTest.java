package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.proto.Drawing;
import touchline.security.Authenticity;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;
import static touchline.model.RobotFramesTest.poseStamped;
import static touchline.model.RobotFramesTest.tf;
import static touchline.model.RobotFramesTest.transform;

/**
 * The field view's frames: automatic is map when a robot names it, a chosen frame places each robot
 * by its own tree, what has no path is left out with the reason, and markers move with their frame.
 */
class FramedFieldTest {

    private final RobotRegistry registry = new RobotRegistry(() -> 1_000_000);
    private final FramedField field = new FramedField();

    private void send(int robot, String topic, touchline.protocol.ros2.RosMessage m) {
        bridged(registry, robot, topic, m);
    }

    /** Robot {@code robot}'s ROS 2 message {@code m} on {@code topic}, as its bridge hands it to the registry. */
    static void bridged(RobotRegistry registry, int robot, String topic, touchline.protocol.ros2.RosMessage m) {
        registry.live().accept(new Envelope(1_000_000, Direction.IN, Channel.BRIDGE,
                InetSocketAddress.createUnresolved("robot", 8765), robot, topic, null, new byte[1], null, Origin.LIVE,
                Authenticity.NOT_CHECKED, m));
    }

    private FramedField.Picture place(Drawing.FieldDrawing markers) {
        return field.place(registry.robots(), registry.frames(Origin.LIVE), Map.of(), markers, 1001, false);
    }

    private static FramedField.Placed robot(FramedField.Picture p, int id) {
        return p.robots().stream().filter(r -> r.robot().id() == id).findFirst().orElseThrow();
    }

    /** Robot 1001: odom at (1, 0) of map turned a quarter, the robot 2 m ahead in odom; robot 1002: a pose in odom only. */
    private void twoRobots() {
        send(1001, "/tf", tf(transform("map", "odom", 1, 0, Math.PI / 2), transform("odom", "base_link", 2, 0, 0)));
        send(1002, "/pose", poseStamped("odom", 0.5, 0.5, 0));
    }

    @Test
    void automaticIsMapAndWhatHasNoPathIsCountedWithItsReason() {
        twoRobots();
        FramedField.Picture p = place(null);
        assertEquals("map", p.frame());
        assertEquals(1000, robot(p, 1001).x(), 1e-6);
        assertEquals(2000, robot(p, 1001).y(), 1e-6);
        assertEquals(1, p.robots().size());
        assertEquals(" · 1 pose not in map: no transform from odom", p.note());
        assertEquals(java.util.Set.of("map", "odom", "base_link"), field.frames());
    }

    @Test
    void aChosenFramePlacesEachRobotByItsOwnTree() {
        twoRobots();
        field.choose("odom");
        FramedField.Picture p = place(null);
        assertEquals(2000, robot(p, 1001).x(), 1e-6);
        assertEquals(0, robot(p, 1001).y(), 1e-6);
        assertEquals(500, robot(p, 1002).x(), 1e-6, "robot 1002's own odom");
        assertEquals("", p.note());

        field.choose("base_link");
        p = place(null);
        assertEquals(0, robot(p, 1001).x(), 1e-6);
        assertEquals(" · 1 pose not in base_link: no transform from odom", p.note());
    }

    @Test
    void withoutMapTheOneFrameOfThePosesIsAutomaticAndSeveralMeanAsGiven() {
        send(1002, "/pose", poseStamped("odom", 0.5, 0.5, 0));
        assertEquals("odom", place(null).frame());
        send(1003, "/pose", poseStamped("world", 3, 0, 0));
        FramedField.Picture p = place(null);
        assertEquals("", p.frame());
        assertEquals(3000, robot(p, 1003).x(), 1e-3, "as given");
    }

    @Test
    void markersMoveIntoTheFrameOrAreLeftOut() {
        twoRobots();
        Drawing.FieldDrawing markers = Drawing.FieldDrawing.newBuilder().setOption("/markers")
                .addShapes(Drawing.FieldShape.newBuilder().setForm(Drawing.FieldShape.Form.CIRCLE).setFrame("base_link")
                        .addXy(1000).addXy(0))
                .addShapes(Drawing.FieldShape.newBuilder().setForm(Drawing.FieldShape.Form.TEXT).setFrame("field")
                        .addXy(0).addXy(0))
                .addShapes(Drawing.FieldShape.newBuilder().setForm(Drawing.FieldShape.Form.DOT).addXy(7).addXy(8)).build();
        FramedField.Picture p = place(markers);
        Drawing.FieldShape ahead = p.markers().getShapes(0);
        // 1 m ahead of the robot, which looks along map's y from (1, 2)
        assertEquals(1000, ahead.getXy(0), 1e-3);
        assertEquals(3000, ahead.getXy(1), 1e-3);
        assertEquals(7, p.markers().getShapes(1).getXy(0), 1e-6, "no frame: as given");
        assertEquals(2, p.markers().getShapesCount());
        assertEquals(1, p.markersNotInFrame());
        assertTrue(p.note().endsWith("1 marker not in map: no transform from field"), p.note());
    }
}
