package touchline.protocol.ros2;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.PythonMcap;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The CDR encoder for a client publish: what it writes, {@link CdrDecoder} reads back as written,
 * and its bytes are the real Python {@code mcap_ros2} serializer's for the same values, byte for
 * byte; values that do not fit are refused naming the field.
 */
class CdrEncoderTest {

    private static MessageDefinition definition(String root, String text) {
        DefinitionResult r = new DefinitionParser().parse(root, "ros2msg", text);
        return assertInstanceOf(DefinitionResult.Parsed.class, r, r.toString()).definition();
    }

    private static MessageDefinition real(String type) {
        return definition(type, Ros2Sources.definition(type));
    }

    private static byte[] encoded(MessageDefinition d, String json) {
        EncodeResult r = new CdrEncoder(d).encode(json);
        return assertInstanceOf(EncodeResult.Encoded.class, r, r.toString()).bytes();
    }

    private static RosMessage roundTrip(MessageDefinition d, String json) {
        DecodeResult r = new CdrDecoder(d).decode(encoded(d, json));
        return assertInstanceOf(DecodeResult.Decoded.class, r, r.toString()).message();
    }

    private static String refusal(MessageDefinition d, String json) {
        EncodeResult r = new CdrEncoder(d).encode(json);
        return assertInstanceOf(EncodeResult.Refused.class, r, r.toString()).reason();
    }

    /** The values each interop type is written with, as a person would type them. */
    static final Map<String, String> VALUES = new LinkedHashMap<>();

    static {
        String header = "{\"stamp\":{\"sec\":1733390000,\"nanosec\":123456789},\"frame_id\":\"map\"}";
        String pose = "{\"position\":{\"x\":1.5,\"y\":-2.25,\"z\":0.125},"
                + "\"orientation\":{\"x\":0.0,\"y\":0.0,\"z\":0.7071067811865476,\"w\":0.7071067811865476}}";
        VALUES.put("tf2_msgs/msg/TFMessage", "{\"transforms\":[{\"header\":" + header + ",\"child_frame_id\":\"head\","
                + "\"transform\":{\"translation\":{\"x\":0.0,\"y\":0.0,\"z\":0.5},"
                + "\"rotation\":{\"x\":0.0,\"y\":0.5,\"z\":0.0,\"w\":0.8660254037844386}}}]}");
        VALUES.put("rcl_interfaces/msg/Log", "{\"stamp\":{\"sec\":7,\"nanosec\":8},\"level\":20,\"name\":\"walker\","
                + "\"msg\":\"kick off — ü\",\"file\":\"walk.cpp\",\"function\":\"step\",\"line\":4294967295}");
        VALUES.put("geometry_msgs/msg/PoseStamped", "{\"header\":" + header + ",\"pose\":" + pose + "}");
        VALUES.put("sensor_msgs/msg/JointState", "{\"header\":" + header + ",\"name\":[\"a\",\"bc\",\"def\"],"
                + "\"position\":[0.1,0.2,0.3],\"velocity\":[],\"effort\":[1.0,-2.0,3.5]}");
        VALUES.put("sensor_msgs/msg/Image", "{\"header\":" + header + ",\"height\":1,\"width\":3,\"encoding\":\"mono8\","
                + "\"is_bigendian\":0,\"step\":3,\"data\":[0,128,255]}");
        VALUES.put("diagnostic_msgs/msg/DiagnosticArray", "{\"header\":" + header + ",\"status\":[{\"level\":1,"
                + "\"name\":\"battery\",\"message\":\"low\",\"hardware_id\":\"bms0\",\"values\":[{\"key\":\"v\","
                + "\"value\":\"21.7\"}]},{\"level\":2,\"name\":\"knee\",\"message\":\"\",\"hardware_id\":\"\",\"values\":[]}]}");
        VALUES.put("geometry_msgs/msg/Pose2D", "{\"x\":1.0,\"y\":-2.0,\"theta\":0.5}");
    }

    @Test
    void whatItWritesDecodesAsWritten() {
        RosMessage pose = roundTrip(real("geometry_msgs/msg/PoseStamped"), VALUES.get("geometry_msgs/msg/PoseStamped"));
        assertEquals(1733390000, pose.at("header.stamp.sec"));
        assertEquals(123456789L, pose.at("header.stamp.nanosec"));
        assertEquals("map", pose.at("header.frame_id"));
        assertEquals(-2.25, pose.number("pose.position.y"));
        assertEquals(0.7071067811865476, pose.number("pose.orientation.w"));

        RosMessage joints = roundTrip(real("sensor_msgs/msg/JointState"), VALUES.get("sensor_msgs/msg/JointState"));
        assertArrayEquals(new String[]{"a", "bc", "def"}, (String[]) joints.get("name"));
        assertArrayEquals(new double[]{1.0, -2.0, 3.5}, (double[]) joints.get("effort"));
        assertEquals(0, ((double[]) joints.get("velocity")).length);

        RosMessage log = roundTrip(real("rcl_interfaces/msg/Log"), VALUES.get("rcl_interfaces/msg/Log"));
        assertEquals(4294967295L, log.get("line"));
        assertEquals("step", log.get("function"));
    }

    @Test
    void everyPrimitiveShapeAndTheEdgesOfTheirRanges() {
        MessageDefinition d = definition("t/msg/All", """
                bool b
                int8 i8
                uint8 u8
                int16 i16
                uint16 u16
                int32 i32
                uint32 u32
                int64 i64
                uint64 u64
                float32 f32
                float64 f64
                string s
                string<=4 bounded
                wstring w
                int16[3] fixed
                float64[<=2] upto
                t/Inner[2] inners
                t/Empty empty
                ================================================================================
                MSG: t/Inner
                byte x
                float64 y
                ================================================================================
                MSG: t/Empty
                """);
        RosMessage m = roundTrip(d, "{\"b\":true,\"i8\":-128,\"u8\":255,\"i16\":-32768,\"u16\":65535,"
                + "\"i32\":-2147483648,\"u32\":4294967295,\"i64\":-9223372036854775808,\"u64\":18446744073709551615,"
                + "\"f32\":0.5,\"f64\":-1e300,\"s\":\"\",\"bounded\":\"abcd\",\"w\":\"wö\",\"fixed\":[1,-2,3],"
                + "\"upto\":[2.5],\"inners\":[{\"x\":7,\"y\":0.25},{}]}");
        assertEquals(true, m.get("b"));
        assertEquals(-128, m.get("i8"));
        assertEquals(255, m.get("u8"));
        assertEquals(-32768, m.get("i16"));
        assertEquals(65535, m.get("u16"));
        assertEquals(-2147483648, m.get("i32"));
        assertEquals(4294967295L, m.get("u32"));
        assertEquals(Long.MIN_VALUE, m.get("i64"));
        assertEquals(-1L, m.get("u64"), "2^64-1 has all bits set");
        assertEquals(0.5f, m.get("f32"));
        assertEquals(-1e300, m.get("f64"));
        assertEquals("abcd", m.get("bounded"));
        assertEquals("wö", m.get("w"));
        assertArrayEquals(new short[]{1, -2, 3}, (short[]) m.get("fixed"));
        assertEquals(7.0, m.number("inners[0].x"));
        assertEquals(0.25, m.number("inners[0].y"));
        assertEquals(0.0, m.number("inners[1].y"), "a field left out is zero");
    }

    @Test
    void valuesThatDoNotFitAreRefusedNamingTheField() {
        MessageDefinition pose = real("geometry_msgs/msg/PoseStamped");
        assertEquals("geometry_msgs/msg/Point has no field pose.position.w", refusal(pose,
                "{\"pose\":{\"position\":{\"w\":1}}}"));
        assertEquals("header.stamp.sec is int32: a whole number is needed, not 1.5",
                refusal(pose, "{\"header\":{\"stamp\":{\"sec\":1.5}}}"));
        assertEquals("header.stamp.nanosec is uint32: -1 is outside 0 to 4294967295",
                refusal(pose, "{\"header\":{\"stamp\":{\"nanosec\":-1}}}"));
        assertEquals("header.frame_id is string: a \"text\" is needed, not 5", refusal(pose, "{\"header\":{\"frame_id\":5}}"));
        assertEquals("pose.position.x is float64: a number is needed, not far", refusal(pose,
                "{\"pose\":{\"position\":{\"x\":\"far\"}}}"));
        assertEquals("pose is geometry_msgs/msg/Pose: an object {..} is needed, not 3", refusal(pose, "{\"pose\":3}"));
        assertTrue(refusal(pose, "pose = 3").startsWith("not a JSON object: "));
        MessageDefinition d = definition("t/msg/A", "int16[2] fixed\nuint8[<=1] upto\nbool b\n");
        assertEquals("fixed is int16[2]: exactly 2 values, not 3", refusal(d, "{\"fixed\":[1,2,3]}"));
        assertEquals("upto is uint8[<=1]: at most 1 values, not 2", refusal(d, "{\"upto\":[1,2]}"));
        assertEquals("upto is uint8[<=1]: a list [..] is needed, not 1", refusal(d, "{\"upto\":1}"));
        assertEquals("b is bool: true or false, not 1", refusal(d, "{\"b\":1}"));
    }

    /** argv: a directory of TYPE.msg and TYPE.json files (slashes as '.'); writes TYPE.cdr by mcap_ros2. */
    static final String SERIALIZE = """
            import json, os, sys
            from mcap_ros2._dynamic import serialize_dynamic
            d = sys.argv[1]
            for f in sorted(os.listdir(d)):
                if f.endswith('.json'):
                    base = f[:-5]
                    name = base.replace('.', '/')
                    enc = serialize_dynamic(name, open(os.path.join(d, base + '.msg')).read())[name]
                    value = json.load(open(os.path.join(d, f), encoding='utf-8'))
                    open(os.path.join(d, base + '.cdr'), 'wb').write(enc(value))
            """;

    @Test
    @Tag("interop")
    void itsBytesAreTheMcapRos2SerializersByteForByte(@TempDir Path dir) throws Exception {
        PythonMcap.require("mcap_ros2");
        for (Map.Entry<String, String> e : VALUES.entrySet()) {
            String base = e.getKey().replace('/', '.');
            Files.writeString(dir.resolve(base + ".msg"), Ros2Sources.definition(e.getKey()));
            Files.writeString(dir.resolve(base + ".json"), e.getValue());
        }
        PythonMcap.run(SERIALIZE, dir);
        for (Map.Entry<String, String> e : VALUES.entrySet()) {
            byte[] python = Files.readAllBytes(dir.resolve(e.getKey().replace('/', '.') + ".cdr"));
            assertArrayEquals(python, encoded(real(e.getKey()), e.getValue()), e.getKey());
        }
    }
}
