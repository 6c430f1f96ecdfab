package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.protocol.ros2.RosMessage;
import touchline.security.Authenticity;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static touchline.model.RosReadingsTest.msg;

/**
 * A ROS 2 robot's frames as its messages tell them (trees as the CDR decoder makes them): TF links
 * and framed poses read from the messages, kept per robot by the registry, and its pose in the
 * Robots table placed in map when its tree leads there.
 */
class RobotFramesTest {

    private static final double EPS = 1e-6;

    static RosMessage header(String frame) {
        return msg("std_msgs/msg/Header", "frame_id", frame);
    }

    static RosMessage quaternion(double yaw) {
        return msg("geometry_msgs/msg/Quaternion", "x", 0.0, "y", 0.0, "z", Math.sin(yaw / 2), "w", Math.cos(yaw / 2));
    }

    static RosMessage transform(String parent, String child, double x, double y, double yaw) {
        return msg("geometry_msgs/msg/TransformStamped", "header", header(parent), "child_frame_id", child,
                "transform", msg("geometry_msgs/msg/Transform",
                        "translation", msg("geometry_msgs/msg/Vector3", "x", x, "y", y, "z", 0.0), "rotation", quaternion(yaw)));
    }

    static RosMessage tf(RosMessage... transforms) {
        return msg("tf2_msgs/msg/TFMessage", "transforms", transforms);
    }

    static RosMessage poseStamped(String frame, double x, double y, double yaw) {
        return msg("geometry_msgs/msg/PoseStamped", "header", header(frame), "pose", msg("geometry_msgs/msg/Pose",
                "position", msg("geometry_msgs/msg/Point", "x", x, "y", y, "z", 0.0), "orientation", quaternion(yaw)));
    }

    private final RosReadings readings = new RosReadings();

    @Test
    void tfMessagesGiveLinksWithoutRos1sSlashAndNonsenseLeftOut() {
        List<FrameTree.Link> links = readings.links(tf(transform("/map", "odom", 1, 2, 0.5),
                transform("odom", "", 1, 1, 0), transform("odom", "base_link", Double.NaN, 0, 0)));
        assertEquals(1, links.size(), links.toString());
        assertEquals("map", links.get(0).parent());
        assertEquals("odom", links.get(0).child());
        assertEquals(0.5, links.get(0).transform().yaw(), EPS);
        assertEquals(1, readings.links(transform("odom", "base_link", 1, 0, 0)).size());
        assertTrue(readings.links(poseStamped("map", 1, 1, 0)).isEmpty());
    }

    @Test
    void aPoseKnowsItsFrame() {
        assertEquals("odom", readings.framedPose("/pose", poseStamped("odom", 1, 2, 0)).orElseThrow().frame());
        RosReadings.FramedPose base = readings.framedPose("/tf", tf(transform("map", "odom", 5, 5, 0),
                transform("odom", "base_link", 1, 2, 0))).orElseThrow();
        assertEquals("odom", base.frame(), "the base's parent");
        assertEquals(1, base.pose().x(), EPS);
        assertEquals("", readings.framedPose("/p", msg("geometry_msgs/msg/Pose2D", "x", 1.0, "y", 2.0, "theta", 0.0))
                .orElseThrow().frame(), "a Pose2D has none");
    }

    private static Envelope bridged(int robot, Origin origin, String topic, RosMessage m) {
        return new Envelope(1_000_000, Direction.IN, Channel.BRIDGE, InetSocketAddress.createUnresolved("robot", 8765), robot,
                topic, null, new byte[1], null, origin, Authenticity.NOT_CHECKED, m);
    }

    @Test
    void theRegistryKeepsEachRobotsTreeAndShowsItsPoseInMap() {
        RobotRegistry registry = new RobotRegistry(() -> 1_000_000);
        // odom lies at (1, 2) of map turned a quarter; the robot 3 m ahead in odom
        registry.live().accept(bridged(1001, Origin.LIVE, "/tf", tf(transform("map", "odom", 1, 2, Math.PI / 2),
                transform("odom", "base_link", 3, 0, 0))));
        RobotSnapshot r = registry.robot(1001).orElseThrow();
        assertEquals(1000, r.x(), 1e-3);
        assertEquals(5000, r.y(), 1e-3);
        assertEquals(Math.PI / 2, r.theta(), 1e-6);

        RobotFrames frames = registry.frames(Origin.LIVE).get(1001);
        assertEquals(java.util.Set.of("map", "odom", "base_link"), frames.frames());
        assertEquals(3, frames.poseIn("odom").transform().x(), EPS);
        assertEquals("no transform from map", frames.poseIn("world").reason());

        // another robot's tree is its own, and a pose without map stays as given
        registry.live().accept(bridged(1002, Origin.LIVE, "/pose", poseStamped("odom", 0.5, 0, 0)));
        assertEquals(500, registry.robot(1002).orElseThrow().x(), 1e-3);
        assertEquals("no transform from odom", registry.frames(Origin.LIVE).get(1002).poseIn("map").reason());
        assertTrue(registry.frames(Origin.REPLAY).isEmpty(), "the replay's robots are apart");
    }
}
