package touchline.protocol.ros2;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.PythonMcap;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * CDR bytes made by the real Python {@code mcap_ros2} serializer (a peer nobody here wrote) from
 * the real ROS 2 definitions, decoded by {@link CdrDecoder}: every value comes back as the script
 * set it. The script's values and these assertions are the two halves of the golden pair.
 */
@Tag("interop")
class CdrDecoderInteropTest {

    static final List<String> TYPES = List.of("rcl_interfaces/msg/Log", "geometry_msgs/msg/PoseStamped",
            "sensor_msgs/msg/JointState", "sensor_msgs/msg/Image", "sensor_msgs/msg/CompressedImage",
            "tf2_msgs/msg/TFMessage", "visualization_msgs/msg/MarkerArray", "diagnostic_msgs/msg/DiagnosticArray",
            "geometry_msgs/msg/Pose2D");

    /** argv: directory with TYPE.msg definitions (slashes as '.'); writes TYPE.cdr, and PoseStamped.be.cdr big-endian. */
    static final String SERIALIZE = """
            import io, sys, os
            from mcap_ros2._dynamic import serialize_dynamic, _write_complex_type, _for_each_msgdef
            from mcap_ros2._cdr import CdrWriter, EncapsulationKind
            d = sys.argv[1]
            header = {'stamp': {'sec': 1733390000, 'nanosec': 123456789}, 'frame_id': 'map'}
            pose = {'position': {'x': 1.5, 'y': -2.25, 'z': 0.125},
                    'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.7071067811865476, 'w': 0.7071067811865476}}
            values = {
              'rcl_interfaces/msg/Log': {'stamp': {'sec': 7, 'nanosec': 8}, 'level': 20, 'name': 'walker',
                  'msg': 'kick off in 3 s \\u2014 \\u00fc', 'file': 'walk.cpp', 'function': 'step', 'line': 4294967295},
              'geometry_msgs/msg/PoseStamped': {'header': header, 'pose': pose},
              'sensor_msgs/msg/JointState': {'header': header, 'name': ['joint_%d' % i for i in range(24)],
                  'position': [i * 0.1 for i in range(24)], 'velocity': [i * -0.5 for i in range(24)],
                  'effort': [i * 2.0 for i in range(24)]},
              'sensor_msgs/msg/Image': {'header': header, 'height': 4, 'width': 3, 'encoding': 'rgb8',
                  'is_bigendian': 0, 'step': 9, 'data': bytes(range(36))},
              'sensor_msgs/msg/CompressedImage': {'header': {'stamp': {'sec': 1, 'nanosec': 2}, 'frame_id': 'cam'},
                  'format': 'jpeg', 'data': b'\\xff\\xd8\\xff\\xe0' + bytes(1000) + b'\\xff\\xd9'},
              'tf2_msgs/msg/TFMessage': {'transforms': [
                  {'header': {'stamp': {'sec': 3, 'nanosec': 4}, 'frame_id': 'odom'}, 'child_frame_id': 'base_link',
                   'transform': {'translation': {'x': 1.0, 'y': 2.0, 'z': 3.0},
                                 'rotation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}},
                  {'header': {'stamp': {'sec': 3, 'nanosec': 5}, 'frame_id': 'base_link'}, 'child_frame_id': 'head',
                   'transform': {'translation': {'x': 0.0, 'y': 0.0, 'z': 0.5},
                                 'rotation': {'x': 0.0, 'y': 0.5, 'z': 0.0, 'w': 0.8660254037844386}}}]},
              'visualization_msgs/msg/MarkerArray': {'markers': [
                  {'header': header, 'ns': 'ball', 'id': 7, 'type': 2, 'action': 0, 'pose': pose,
                   'scale': {'x': 0.1, 'y': 0.1, 'z': 0.1}, 'color': {'r': 1.0, 'g': 0.5, 'b': 0.0, 'a': 1.0},
                   'lifetime': {'sec': 0, 'nanosec': 500000000}, 'frame_locked': True,
                   'points': [{'x': 0.0, 'y': 0.0, 'z': 0.0}, {'x': 1.0, 'y': -1.0, 'z': 0.0}],
                   'colors': [], 'texture_resource': '', 'texture': {'header': header, 'format': '', 'data': b''},
                   'uv_coordinates': [{'u': 0.25, 'v': 0.75}], 'text': 'ball', 'mesh_resource': '',
                   'mesh_file': {'filename': 'ball.stl', 'data': b'solid'}, 'mesh_use_embedded_materials': False},
                  {'header': header, 'ns': 'line', 'id': -1, 'type': 4, 'action': 3, 'pose': pose,
                   'scale': {'x': 0.02, 'y': 0.0, 'z': 0.0}, 'color': {'r': 0.0, 'g': 0.0, 'b': 1.0, 'a': 0.5},
                   'lifetime': {'sec': 1, 'nanosec': 0}, 'frame_locked': False, 'points': [],
                   'colors': [{'r': 0.1, 'g': 0.2, 'b': 0.3, 'a': 0.4}], 'texture_resource': '',
                   'texture': {'header': header, 'format': 'png', 'data': b'\\x89PNG'}, 'uv_coordinates': [],
                   'text': '', 'mesh_resource': 'package://m.dae', 'mesh_file': {'filename': '', 'data': b''},
                   'mesh_use_embedded_materials': True}]},
              'diagnostic_msgs/msg/DiagnosticArray': {'header': header, 'status': [
                  {'level': 1, 'name': 'battery', 'message': 'low', 'hardware_id': 'bms0',
                   'values': [{'key': 'voltage', 'value': '21.7'}, {'key': 'temperature', 'value': '41'}]},
                  {'level': 2, 'name': 'knee', 'message': 'hot', 'hardware_id': '', 'values': []}]},
              'geometry_msgs/msg/Pose2D': {'x': 1.0, 'y': -2.0, 'theta': 0.5},
            }
            for name, value in values.items():
                text = open(os.path.join(d, name.replace('/', '.') + '.msg')).read()
                enc = serialize_dynamic(name, text)[name]
                open(os.path.join(d, name.replace('/', '.') + '.cdr'), 'wb').write(enc(value))
            # the same PoseStamped big-endian: mcap_ros2's own writer, told CDR_BE
            name = 'geometry_msgs/msg/PoseStamped'
            msgdefs = {}
            _for_each_msgdef(name, open(os.path.join(d, name.replace('/', '.') + '.msg')).read(),
                             lambda full, short, m: (msgdefs.__setitem__(full, m), msgdefs.__setitem__(short, m)))
            from mcap_ros2._dynamic import TimeDefinition
            msgdefs['builtin_interfaces/Time'] = TimeDefinition
            out = io.BytesIO()
            w = CdrWriter(out, kind=EncapsulationKind.CDR_BE)
            _write_complex_type(msgdefs[name].msg_name, msgdefs[name].fields, msgdefs, values[name], w)
            open(os.path.join(d, 'PoseStamped.be.cdr'), 'wb').write(out.getvalue())
            """;

    @TempDir
    static Path dir;

    @BeforeAll
    static void serialize() throws Exception {
        PythonMcap.require("mcap_ros2");
        for (String t : TYPES) {
            Files.writeString(dir.resolve(t.replace('/', '.') + ".msg"), Ros2Sources.definition(t));
        }
        PythonMcap.run(SERIALIZE, dir);
    }

    static RosMessage decode(String type, String file) throws Exception {
        DefinitionResult r = new DefinitionParser().parse(type, "ros2msg", Ros2Sources.definition(type));
        MessageDefinition def = assertInstanceOf(DefinitionResult.Parsed.class, r, r.toString()).definition();
        DecodeResult d = new CdrDecoder(def).decode(Files.readAllBytes(dir.resolve(file)));
        return assertInstanceOf(DecodeResult.Decoded.class, d, d.toString()).message();
    }

    static RosMessage decode(String type) throws Exception {
        return decode(type, type.replace('/', '.') + ".cdr");
    }

    static void assertHeader(RosMessage m) {
        assertEquals(1733390000, m.at("header.stamp.sec"));
        assertEquals(123456789L, m.at("header.stamp.nanosec"));
        assertEquals("map", m.at("header.frame_id"));
    }

    @Test
    void log() throws Exception {
        RosMessage m = decode("rcl_interfaces/msg/Log");
        assertEquals("rcl_interfaces/msg/Log", m.typeName());
        assertEquals(7, m.at("stamp.sec"));
        assertEquals(8L, m.at("stamp.nanosec"));
        assertEquals(20, m.get("level"));
        assertEquals("walker", m.get("name"));
        assertEquals("kick off in 3 s — ü", m.get("msg"));
        assertEquals("walk.cpp", m.get("file"));
        assertEquals("step", m.get("function"));
        assertEquals(4294967295L, m.get("line"));
        assertEquals(4294967295.0, m.number("line"));
        assertEquals(List.of("stamp.sec", "stamp.nanosec", "level", "line"), m.numericPaths());
    }

    @Test
    void poseStampedLittleAndBigEndianDecodeAlike() throws Exception {
        for (String file : new String[]{"geometry_msgs.msg.PoseStamped.cdr", "PoseStamped.be.cdr"}) {
            byte[] raw = Files.readAllBytes(dir.resolve(file));
            assertEquals(file.contains(".be.") ? 0 : 1, raw[1], "the encapsulation " + file + " carries");
            RosMessage m = decode("geometry_msgs/msg/PoseStamped", file);
            assertHeader(m);
            assertEquals(1.5, m.number("pose.position.x"));
            assertEquals(-2.25, m.number("pose.position.y"));
            assertEquals(0.125, m.number("pose.position.z"));
            assertEquals(0.7071067811865476, m.number("pose.orientation.w"));
            assertEquals(List.of("header.stamp.sec", "header.stamp.nanosec", "pose.position.x", "pose.position.y",
                    "pose.position.z", "pose.orientation.x", "pose.orientation.y", "pose.orientation.z",
                    "pose.orientation.w"), m.numericPaths());
        }
    }

    @Test
    void jointStateWith24Joints() throws Exception {
        RosMessage m = decode("sensor_msgs/msg/JointState");
        assertHeader(m);
        String[] names = (String[]) m.get("name");
        assertEquals(24, names.length);
        assertEquals("joint_23", names[23]);
        double[] position = (double[]) m.get("position");
        assertEquals(24, position.length);
        assertEquals(2.3000000000000003, position[23]);
        assertEquals(-11.5, m.number("velocity[23]"));
        assertEquals(46.0, m.number("effort[23]"));
        assertEquals(2 + 3 * 24, m.numericPaths().size());
        assertTrue(m.numericPaths().contains("position[3]"));
    }

    @Test
    void imageKeepsItsDataAsOneArray() throws Exception {
        RosMessage m = decode("sensor_msgs/msg/Image");
        assertHeader(m);
        assertEquals(4L, m.get("height"));
        assertEquals(3L, m.get("width"));
        assertEquals("rgb8", m.get("encoding"));
        assertEquals(0, m.get("is_bigendian"));
        assertEquals(9L, m.get("step"));
        byte[] expected = new byte[36];
        for (int i = 0; i < 36; i++) {
            expected[i] = (byte) i;
        }
        assertArrayEquals(expected, (byte[]) m.get("data"));
        assertEquals(35.0, m.number("data[35]"));
        assertTrue(m.numericPaths().stream().noneMatch(p -> p.startsWith("data")), "image bytes are no plot fields");
    }

    @Test
    void compressedImage() throws Exception {
        RosMessage m = decode("sensor_msgs/msg/CompressedImage");
        assertEquals("cam", m.at("header.frame_id"));
        assertEquals("jpeg", m.get("format"));
        byte[] data = (byte[]) m.get("data");
        assertEquals(1006, data.length);
        assertEquals((byte) 0xFF, data[0]);
        assertEquals((byte) 0xD8, data[1]);
        assertEquals((byte) 0xD9, data[1005]);
        assertEquals("{header: {stamp: {sec: 1, nanosec: 2}, frame_id: \"cam\"}, format: \"jpeg\", data: <1006 bytes>}",
                m.line(200));
    }

    @Test
    void tfMessage() throws Exception {
        RosMessage m = decode("tf2_msgs/msg/TFMessage");
        RosMessage[] t = (RosMessage[]) m.get("transforms");
        assertEquals(2, t.length);
        assertEquals("odom", t[0].at("header.frame_id"));
        assertEquals("base_link", t[0].get("child_frame_id"));
        assertEquals(3.0, t[0].number("transform.translation.z"));
        assertEquals(5L, m.at("transforms[1].header.stamp.nanosec"));
        assertEquals("head", m.at("transforms[1].child_frame_id"));
        assertEquals(0.8660254037844386, m.number("transforms[1].transform.rotation.w"));
        assertTrue(m.numericPaths().contains("transforms[1].transform.rotation.w"));
    }

    @Test
    void markerArray() throws Exception {
        RosMessage m = decode("visualization_msgs/msg/MarkerArray");
        RosMessage[] markers = (RosMessage[]) m.get("markers");
        assertEquals(2, markers.length);
        RosMessage ball = markers[0];
        assertEquals("ball", ball.get("ns"));
        assertEquals(7, ball.get("id"));
        assertEquals(2, ball.get("type"));
        assertEquals(0.5f, ball.at("color.g"));
        assertEquals(500000000L, ball.at("lifetime.nanosec"));
        assertEquals(Boolean.TRUE, ball.get("frame_locked"));
        assertEquals(-1.0, ball.number("points[1].y"));
        assertEquals(0.75f, ball.at("uv_coordinates[0].v"));
        assertEquals("ball.stl", ball.at("mesh_file.filename"));
        assertArrayEquals("solid".getBytes(), (byte[]) ball.at("mesh_file.data"));
        RosMessage line = markers[1];
        assertEquals(-1, line.get("id"));
        assertEquals(3, line.get("action"));
        assertEquals(0, ((RosMessage[]) line.get("points")).length);
        assertEquals(0.4f, line.at("colors[0].a"));
        assertEquals("png", line.at("texture.format"));
        assertEquals("package://m.dae", line.get("mesh_resource"));
        assertEquals(Boolean.TRUE, line.get("mesh_use_embedded_materials"));
        assertEquals(1.0, m.number("markers[1].mesh_use_embedded_materials"));
    }

    @Test
    void diagnosticArray() throws Exception {
        RosMessage m = decode("diagnostic_msgs/msg/DiagnosticArray");
        assertHeader(m);
        assertEquals(1, m.at("status[0].level"));
        assertEquals("battery", m.at("status[0].name"));
        assertEquals("voltage", m.at("status[0].values[0].key"));
        assertEquals("41", m.at("status[0].values[1].value"));
        assertEquals(2, m.at("status[1].level"));
        assertEquals("hot", m.at("status[1].message"));
        assertEquals(0, ((RosMessage[]) m.at("status[1].values")).length);
    }

    @Test
    void pose2d() throws Exception {
        RosMessage m = decode("geometry_msgs/msg/Pose2D");
        assertEquals(1.0, m.get("x"));
        assertEquals(-2.0, m.get("y"));
        assertEquals(0.5, m.get("theta"));
        assertEquals("x: 1.0\ny: -2.0\ntheta: 0.5\n", m.text(1000));
    }

    @Test
    void everyCutOfEveryMessageIsAnErrorNeverAnException() throws Exception {
        for (String t : TYPES) {
            DefinitionResult r = new DefinitionParser().parse(t, "ros2msg", Ros2Sources.definition(t));
            CdrDecoder decoder = new CdrDecoder(((DefinitionResult.Parsed) r).definition());
            byte[] whole = Files.readAllBytes(dir.resolve(t.replace('/', '.') + ".cdr"));
            int undecodable = 0;
            for (int cut = 0; cut < whole.length; cut++) {
                if (decoder.decode(whole, 0, cut) instanceof DecodeResult.Undecodable) {
                    undecodable++;
                }
            }
            // none of these messages ends in padding, so every shorter one lacks bytes of a field
            assertEquals(whole.length, undecodable, t + ": every shorter message is refused");
        }
    }
}
