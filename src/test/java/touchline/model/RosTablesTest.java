package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.ros2.RosMessage;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Joint states and diagnostics as the tables the table view shows, and images as the image view's data. */
class RosTablesTest {

    private static RosMessage msg(String type, String[] names, Object... values) {
        return new RosMessage(type, null, names, values);
    }

    @Test
    void aJointStateIsARowPerJoint() {
        RosMessage js = msg("sensor_msgs/msg/JointState", new String[] {"name", "position", "velocity", "effort"},
                new String[] {"head_yaw", "l_knee"}, new double[] {0.5, -1.25}, new double[] {0.1}, new double[0]);
        Fumanoid.DebugTable t = new RosTables().table("/joint_states", js).orElseThrow();
        assertEquals("/joint_states", t.getOption());
        assertEquals(List.of("joint", "position", "velocity", "effort"), t.getHeaderList());
        assertEquals(List.of("head_yaw", "0.500", "0.100", ""), t.getRows(0).getCellsList());
        assertEquals(List.of("l_knee", "-1.250", "", ""), t.getRows(1).getCellsList());
    }

    @Test
    void aDiagnosticArrayIsARowPerStatusWithItsValues() {
        String[] kvNames = {"key", "value"};
        RosMessage status = msg("diagnostic_msgs/msg/DiagnosticStatus",
                new String[] {"level", "name", "message", "hardware_id", "values"}, 1, "motors", "warm", "joints",
                new RosMessage[] {msg("diagnostic_msgs/msg/KeyValue", kvNames, "Temperature", "52.5"),
                        msg("diagnostic_msgs/msg/KeyValue", kvNames, "Load", "0.4")});
        RosMessage array = msg("diagnostic_msgs/msg/DiagnosticArray", new String[] {"status"},
                (Object) new RosMessage[] {status});
        Fumanoid.DebugTable t = new RosTables().table("/diagnostics", array).orElseThrow();
        assertEquals(List.of("name", "level", "message", "hardware", "values"), t.getHeaderList());
        assertEquals(List.of("motors", "WARN", "warm", "joints", "Temperature=52.5, Load=0.4"), t.getRows(0).getCellsList());
    }

    @Test
    void otherTypesAreNoTable() {
        assertTrue(new RosTables().table("/x", msg("std_msgs/msg/String", new String[] {"data"}, "hi")).isEmpty());
    }

    @Test
    void imagesBecomeTheImageViewsDataAndTablesTheTableViews() {
        RosDebugData data = new RosDebugData();
        RosMessage rgb = msg("sensor_msgs/msg/Image", new String[] {"height", "width", "encoding", "step", "data"},
                1, 1, "bgr8", 3L, new byte[] {1, 2, 3});
        RosDebugData.Data d = data.of(1001, "/camera", rgb).orElseThrow();
        assertEquals(Fumanoid.DebugKind.IMAGE_VALUE, d.debugKind());
        Fumanoid.DebugImage img = (Fumanoid.DebugImage) d.data();
        assertEquals("/camera", img.getOption());
        assertEquals(Fumanoid.ImageFormat.RGB888_VALUE, img.getFormat());
        assertArrayEquals(new byte[] {3, 2, 1}, img.getData().toByteArray());
        RosMessage bad = msg("sensor_msgs/msg/Image", new String[] {"height", "width", "encoding", "step", "data"},
                1, 1, "bayer_rggb8", 1L, new byte[] {1});
        Fumanoid.DebugText why = (Fumanoid.DebugText) data.of(1001, "/camera", bad).orElseThrow().data();
        assertTrue(why.getText().contains("bayer_rggb8"), why.getText());
        assertEquals("/camera", why.getOption());
        RosMessage js = msg("sensor_msgs/msg/JointState", new String[] {"name"}, (Object) new String[] {"a"});
        assertEquals(Fumanoid.DebugKind.TABLE_VALUE, data.of(1001, "/joint_states", js).orElseThrow().debugKind());
    }
}
