package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.protocol.ros2.RosMessage;

import java.io.IOException;
import java.io.StringReader;

import static org.junit.jupiter.api.Assertions.*;

/** What a ROS 2 robot's messages say of it, by type and by the user's mapping (trees as the decoders make them). */
class RosReadingsTest {

    static RosMessage msg(String type, Object... namesAndValues) {
        String[] names = new String[namesAndValues.length / 2];
        Object[] values = new Object[names.length];
        for (int i = 0; i < names.length; i++) {
            names[i] = (String) namesAndValues[2 * i];
            values[i] = namesAndValues[2 * i + 1];
        }
        return new RosMessage(type, null, names, values);
    }

    private static RosMessage transform(String child, double x, double y, double yaw) {
        return msg("geometry_msgs/msg/TransformStamped", "child_frame_id", child, "transform", msg("geometry_msgs/msg/Transform",
                "translation", msg("geometry_msgs/msg/Vector3", "x", x, "y", y, "z", 0.0),
                "rotation", msg("geometry_msgs/msg/Quaternion", "x", 0.0, "y", 0.0, "z", Math.sin(yaw / 2), "w",
                        Math.cos(yaw / 2))));
    }

    private final RosReadings readings = new RosReadings();

    @Test
    void pose2DAndTheTfTransformOfTheBaseArePoses() {
        assertEquals(new RosReadings.Pose(1.0, -2.0, 0.5),
                readings.pose("/p", msg("geometry_msgs/msg/Pose2D", "x", 1.0, "y", -2.0, "theta", 0.5)).orElseThrow());
        RosMessage tf = msg("tf2_msgs/msg/TFMessage", "transforms", new RosMessage[]{
                transform("camera", 9, 9, 0), transform("base_link", 0.5, 0.25, Math.PI / 2)});
        RosReadings.Pose p = readings.pose("/tf", tf).orElseThrow();
        assertEquals(0.5, p.x(), 1e-9);
        assertEquals(0.25, p.y(), 1e-9);
        assertEquals(Math.PI / 2, p.theta(), 1e-9);
        assertTrue(readings.pose("/odd", msg("std_msgs/msg/Float64", "x", 1.0, "y", 2.0)).isEmpty(),
                "an unknown type is no pose unless mapped");
    }

    @Test
    void aBatteryFieldIsFoundByNameInNestedMessagesAndArraysOfThemAndNotElsewhere() {
        RosMessage nested = msg("my/Power", "supply", msg("my/Supply", "Battery", msg("my/Level", "PerCent", 64.0)));
        assertEquals(64, readings.batteryPercent("/power", nested).orElseThrow());
        RosMessage packs = msg("my/Packs", "packs", new RosMessage[] {msg("my/Pack", "voltage", 24.0),
                msg("my/Pack", "battery_percentage", 0.5)});
        assertEquals(50, readings.batteryPercent("/packs", packs).orElseThrow());
        assertTrue(readings.batteryPercent("/joints", msg("sensor_msgs/msg/JointState", "position", new double[] {0.5}))
                .isEmpty());
        assertTrue(readings.batteryPercent("/s", msg("x", "percent", 40.0)).isEmpty(), "a percent of no battery");
        assertTrue(packs.namesContain("BATTERY"));
        assertFalse(packs.namesContain("temperature"));
    }

    @Test
    void batteryGameStateAndLogByTypeAndByName() {
        assertEquals(87, readings.batteryPercent("/battery", msg("sensor_msgs/msg/BatteryState", "percentage", 0.87f))
                .orElseThrow());
        assertEquals(40, readings.batteryPercent("/s", msg("x", "battery_percent", 40L)).orElseThrow());
        assertEquals("PLAYING", readings.gameState("/gc", msg("game_controller_hl_interfaces/msg/GameState",
                "game_state", 3)).orElseThrow(), "the GameController's number");
        assertEquals("READY", readings.gameState("/s", msg("x", "gameState", "state_ready")).orElseThrow());
        assertTrue(readings.gameState("/s", msg("x", "game_state", "HALFTIME")).isEmpty());
        assertEquals(new RosReadings.LogLine("ERROR", "walker", "fell"), readings.log("/rosout",
                msg("rcl_interfaces/msg/Log", "level", 40, "name", "walker", "msg", "fell")).orElseThrow());
    }

    @Test
    void theMappingNamesWhatTheTypesDoNotSay() throws IOException {
        RosReadings mapped = new RosReadings(RosMapping.parse(new StringReader(
                "pose=/loc\nlog=/say\nbattery./power=level\ngameState./ref=s\n")));
        assertEquals(new RosReadings.Pose(1.0, 2.0, 0.0),
                mapped.pose("/loc", msg("my/Loc", "x", 1.0, "y", 2.0, "theta", 0.0)).orElseThrow());
        assertEquals(55, mapped.batteryPercent("/power", msg("my/Power", "level", 55.0)).orElseThrow());
        assertEquals("SET", mapped.gameState("/ref", msg("my/Ref", "s", "SET")).orElseThrow());
        assertEquals("hello", mapped.log("/say", msg("std_msgs/msg/String", "data", "hello")).orElseThrow().text());
        assertTrue(readings.batteryPercent("/power", msg("my/Power", "level", 55.0)).isEmpty(), "not without the mapping");
    }
}
