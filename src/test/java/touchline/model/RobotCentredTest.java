package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.proto.Drawing;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;
import static touchline.model.RobotFramesTest.poseStamped;
import static touchline.model.RobotFramesTest.tf;
import static touchline.model.RobotFramesTest.transform;

/**
 * A ROS 2 robot's surroundings in its own frame: its markers and the other robots (their poses in
 * map by their own trees, a small robot's as it reports it) moved by its tree into base_link or the
 * frame chosen; what has no path is counted with the reason.
 */
class RobotCentredTest {

    private final RobotRegistry registry = new RobotRegistry(() -> 1_000_000);
    private final RobotCentred centred = new RobotCentred();

    private void send(int robot, String topic, touchline.protocol.ros2.RosMessage m) {
        FramedFieldTest.bridged(registry, robot, topic, m);
    }

    /** A small robot reporting (x, y) millimetres of the field. */
    private void small(int id, float x, float y) {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(id).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setRobotPosition(Fumanoid.Position.newBuilder().setX(x).setY(y)).build()).build();
        registry.live().accept(new Envelope(1_000_000, Direction.IN, Channel.FUMANOID,
                new InetSocketAddress("127.0.0.1", 4000 + id), id, "status", m, new byte[40], null));
    }

    private FramedField.Picture place(Drawing.FieldDrawing markers) {
        return centred.place(1001, Origin.LIVE, registry.robots(), registry.frames(Origin.LIVE), markers);
    }

    private static FramedField.Placed robot(FramedField.Picture p, int id) {
        return p.robots().stream().filter(r -> r.robot().id() == id).findFirst().orElseThrow();
    }

    /** Robot 1001: odom at (1, 0) of map turned a quarter, base_link 2 m ahead in odom (so at (1, 2) of map looking along y), a camera 0.1 m ahead. */
    private void observer() {
        send(1001, "/tf", tf(transform("map", "odom", 1, 0, Math.PI / 2), transform("odom", "base_link", 2, 0, 0),
                transform("base_link", "camera", 0.1, 0, 0)));
    }

    private static Drawing.FieldDrawing ballAt(String frame, float x, float y) {
        return Drawing.FieldDrawing.newBuilder().setOption("/markers")
                .addShapes(Drawing.FieldShape.newBuilder().setForm(Drawing.FieldShape.Form.DOT).setFrame(frame)
                        .addXy(x).addXy(y)).build();
    }

    @Test
    void aMarkerInMapIsWhereTheRobotsTreePutsItInBaseLink() {
        observer();
        // (1, 3) of map is 1 m ahead of the robot at (1, 2) looking along map's y
        FramedField.Picture p = place(ballAt("map", 1000, 3000));
        assertEquals("base_link", p.frame(), "base_link by default");
        assertEquals(1000, p.markers().getShapes(0).getXy(0), 1e-3);
        assertEquals(0, p.markers().getShapes(0).getXy(1), 1e-3);
        assertEquals("base_link", p.markers().getShapes(0).getFrame());
        assertEquals(Set.of("map", "odom", "base_link", "camera"), centred.frames());

        centred.choose("camera");
        p = place(ballAt("map", 1000, 3000));
        assertEquals(900, p.markers().getShapes(0).getXy(0), 1e-3, "the camera is 0.1 m ahead of the body");
    }

    @Test
    void otherRobotsArePlacedByTheirOwnTreesThroughMap() {
        observer();
        // robot 1002's odom lies elsewhere in map: its own tree puts it at (3, 2) of map, 2 m to the observer's right
        send(1002, "/tf", tf(transform("map", "odom", 3, 0, 0), transform("odom", "base_link", 0, 2, Math.PI)));
        send(1002, "/pose", poseStamped("odom", 0, 2, Math.PI));
        small(3, 1000, 1000); // a small robot 1 m behind the observer
        FramedField.Picture p = place(null);
        assertEquals(0, robot(p, 1002).x(), 1e-6);
        assertEquals(-2000, robot(p, 1002).y(), 1e-6);
        assertEquals(Math.PI / 2, robot(p, 1002).theta(), 1e-6, "looking along map's -x: to the observer's left");
        assertEquals(-1000, robot(p, 3).x(), 1e-3);
        assertEquals(0, robot(p, 3).y(), 1e-3);
        assertTrue(p.robots().stream().noneMatch(r -> r.robot().id() == 1001), "not itself");
        assertEquals("", p.note());
    }

    @Test
    void whatHasNoPathIsLeftOutWithTheReason() {
        observer();
        send(1002, "/pose", poseStamped("odom", 0.5, 0.5, 0)); // odom of a robot that told no tree
        Drawing.FieldDrawing markers = ballAt("field", 0, 0);
        FramedField.Picture p = place(markers);
        assertEquals(0, p.robots().size());
        assertEquals(0, p.markers().getShapesCount());
        assertEquals(" · 1 pose not in base_link: no transform from odom · 1 marker not in base_link: no transform from field",
                p.note());

        // an observer whose tree does not reach map: no other robot can be placed
        send(1003, "/tf", tf(transform("odom", "base_link", 1, 0, 0)));
        small(4, 0, 0);
        p = centred.place(1003, Origin.LIVE, registry.robots(), registry.frames(Origin.LIVE), null);
        assertTrue(p.note().contains("poses not in base_link: no transform from map"), p.note());
        assertEquals(0, p.robots().size());
    }
}
