package touchline.protocol.ros2;

import org.junit.jupiter.api.Test;

import java.io.InputStream;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

class DefinitionParserTest {

    private final DefinitionParser parser = new DefinitionParser();

    private MessageDefinition parsed(String root, String encoding, String text) {
        DefinitionResult r = parser.parse(root, encoding, text);
        return assertInstanceOf(DefinitionResult.Parsed.class, r, r.toString()).definition();
    }

    private DefinitionResult.Refused refused(String root, String encoding, String text) {
        DefinitionResult r = parser.parse(root, encoding, text);
        return assertInstanceOf(DefinitionResult.Refused.class, r, r.toString());
    }

    private static List<String> shapes(MessageType t) {
        return t.fields().stream().map(f -> f.typeText() + " " + f.name()).toList();
    }

    @Test
    void everyPrimitiveShapeConstantDefaultAndComment() {
        MessageDefinition d = parsed("test_msgs/msg/All", "ros2msg", """
                # a comment line
                uint8 DEBUG=10   # a constant with a comment
                string GREETING="hello # not a comment"
                bool b
                byte y
                char c
                int8 i8
                uint8 u8 7            # with a default value
                int16 i16
                uint16 u16
                int32 i32 -5
                uint32 u32
                int64 i64
                uint64 u64
                float32 f32 1.5
                float64 f64
                string s "default text"
                wstring w
                string<=10 bounded
                float64[36] covariance
                int32[<=5] few [1, 2]
                string<=8[] names
                Header header
                Point p
                geometry_msgs/Vector3 v
                builtin_interfaces/msg/Time t
                ================================================================================
                MSG: std_msgs/Header
                builtin_interfaces/Time stamp
                string frame_id
                ================================================================================
                MSG: test_msgs/Point
                float64 x
                ===
                MSG: geometry_msgs/msg/Vector3
                float64 x
                """);
        MessageType all = d.root();
        assertEquals("test_msgs/msg/All", all.name());
        assertEquals(List.of("bool b", "byte y", "char c", "int8 i8", "uint8 u8", "int16 i16", "uint16 u16", "int32 i32",
                "uint32 u32", "int64 i64", "uint64 u64", "float32 f32", "float64 f64", "string s", "wstring w",
                "string<=10 bounded", "float64[36] covariance", "int32[<=5] few", "string<=8[] names",
                "std_msgs/msg/Header header", "test_msgs/msg/Point p", "geometry_msgs/msg/Vector3 v",
                "builtin_interfaces/msg/Time t"), shapes(all));
        assertEquals(List.of(new MessageType.Constant(Primitive.UINT8, "DEBUG", "10"),
                new MessageType.Constant(Primitive.STRING, "GREETING", "\"hello # not a comment\"")), all.constants());
        assertEquals(List.of("builtin_interfaces/msg/Time stamp", "string frame_id"),
                shapes(d.type("std_msgs/msg/Header")));
        assertEquals(List.of("int32 sec", "uint32 nanosec"), shapes(d.type("builtin_interfaces/msg/Time")),
                "Time is built in");
    }

    @Test
    void theRealDefinitionsParse() {
        for (String t : CdrDecoderInteropTest.TYPES) {
            MessageDefinition d = parsed(t, "ros2msg", Ros2Sources.definition(t));
            assertEquals(t, d.rootName());
        }
        MessageType log = parsed("rcl_interfaces/msg/Log", "ros2msg", Ros2Sources.definition("rcl_interfaces/msg/Log"))
                .root();
        assertEquals(List.of("builtin_interfaces/msg/Time stamp", "uint8 level", "string name", "string msg",
                "string file", "string function", "uint32 line"), shapes(log));
        assertEquals(List.of("DEBUG", "INFO", "WARN", "ERROR", "FATAL"),
                log.constants().stream().map(MessageType.Constant::name).toList());
    }

    @Test
    void errorsNameTheLine() {
        assertEquals("line 3: 'float64[' is not a field type",
                refused("a/msg/B", "ros2msg", "int32 x\n\nfloat64[ y\n").reason());
        assertEquals(3, refused("a/msg/B", "ros2msg", "int32 x\n\nfloat64[ y\n").line());
        assertEquals("line 2: 'justaword' is not a field (type name) or a constant (type NAME=value)",
                refused("a/msg/B", "ros2msg", "int32 x\njustaword\n").reason());
        assertEquals("line 3: after a line of '=' a dependency starts with 'MSG: pkg/Type', not 'int32 y'",
                refused("a/msg/B", "ros2msg", "int32 x\n=====\nint32 y\n").reason());
        assertEquals("line 1: 99999999999 is too large a bound",
                refused("a/msg/B", "ros2msg", "int32[99999999999] x\n").reason());
        assertEquals("line 1: a constant is of a single primitive type, not int32[]",
                refused("a/msg/B", "ros2msg", "int32[] X=1\n").reason());
        assertEquals("line 1: only strings have a bound like '<=N', not int32",
                refused("a/msg/B", "ros2msg", "int32<=3 x\n").reason());
    }

    @Test
    void aDefinitionMustBeWhole() {
        DefinitionResult.Refused missing = refused("a/msg/B", "ros2msg", "Missing m\n");
        assertEquals("a/msg/B.m is of type a/msg/Missing, which the schema does not define (a section"
                + " 'MSG: a/Missing' is missing)", missing.reason());
        assertEquals("type a/msg/B contains itself (a/msg/B → a/msg/C → a/msg/B)",
                refused("a/msg/B", "ros2msg", "C c\n===\nMSG: a/C\nB b\n").reason());
        assertEquals("type a/msg/B takes no bytes on the wire (only empty arrays)",
                refused("a/msg/B", "ros2msg", "int32[0] x\n").reason());
        assertEquals("'nopackage' is not a message type name (pkg/msg/Type)",
                refused("nopackage", "ros2msg", "int32 x").reason());
        assertEquals("schema encoding 'ros1msg' is not ros2msg or ros2idl",
                refused("a/msg/B", "ros1msg", "int32 x").reason());
        // recursion through a sequence is fine (a tree), and an empty type is one placeholder byte
        parsed("a/msg/Tree", "ros2msg", "Tree[] children\n");
        assertEquals(List.of(), parsed("std_msgs/msg/Empty", "ros2msg", "# nothing\n").root().fields());
    }

    @Test
    void deepNestingIsRefused() {
        StringBuilder b = new StringBuilder("T1 t\n");
        for (int i = 1; i <= 70; i++) {
            b.append("===\nMSG: a/T").append(i).append('\n').append(i == 70 ? "int32 x" : "T" + (i + 1) + " t").append('\n');
        }
        assertTrue(refused("a/msg/T0", "ros2msg", b.toString()).reason().startsWith("types nest deeper than 64 levels"));
    }

    /** rosidl's IDL of PoseStamped (as rosidl_adapter writes it from the .msg files), in one schema. */
    static final String POSE_STAMPED_IDL = """
            ================================================================================
            IDL: geometry_msgs/msg/PoseStamped
            // generated from rosidl_adapter/resource/msg.idl.em
            // with input from geometry_msgs/msg/PoseStamped.msg
            // generated code does not contain a copyright notice

            #include "geometry_msgs/msg/Pose.idl"
            #include "std_msgs/msg/Header.idl"

            module geometry_msgs {
              module msg {
                @verbatim (language="comment", text=
                  "A Pose with reference coordinate frame and timestamp")
                struct PoseStamped {
                  std_msgs::msg::Header header;

                  geometry_msgs::msg::Pose pose;
                };
              };
            };

            ================================================================================
            IDL: geometry_msgs/msg/Pose
            module geometry_msgs {
              module msg {
                struct Pose {
                  geometry_msgs::msg::Point position;
                  Quaternion orientation;
                };
                struct Point {
                  double x;
                  double y;
                  double z;
                };
                struct Quaternion {
                  @default (value=0.0)
                  double x;
                  @default (value=0.0)
                  double y;
                  @default (value=0.0)
                  double z;
                  @default (value=1.0)
                  double w;
                };
              };
            };
            ================================================================================
            IDL: std_msgs/msg/Header
            #include "builtin_interfaces/msg/Time.idl"
            module std_msgs {
              module msg {
                /* Standard metadata
                   for higher-level stamped data types. */
                struct Header {
                  builtin_interfaces::msg::Time stamp;
                  @verbatim (language="comment", text=
                    "Transform frame with which this data is associated.")
                  string frame_id;
                };
              };
            };
            """;

    @Test
    void idlDefinesTheSameTypesAndDecodesTheSerializersBytes() throws Exception {
        MessageDefinition idl = parsed("geometry_msgs/msg/PoseStamped", "ros2idl", POSE_STAMPED_IDL);
        MessageDefinition msg = parsed("geometry_msgs/msg/PoseStamped", "ros2msg",
                Ros2Sources.definition("geometry_msgs/msg/PoseStamped"));
        for (String t : List.of("geometry_msgs/msg/PoseStamped", "geometry_msgs/msg/Pose", "geometry_msgs/msg/Point",
                "geometry_msgs/msg/Quaternion", "std_msgs/msg/Header")) {
            assertEquals(shapes(msg.type(t)), shapes(idl.type(t)), t);
        }
        byte[] golden;
        try (InputStream in = getClass().getResourceAsStream("/ros2/cdr/geometry_msgs.msg.PoseStamped.cdr")) {
            golden = in.readAllBytes();
        }
        DecodeResult r = new CdrDecoder(idl).decode(golden);
        RosMessage m = assertInstanceOf(DecodeResult.Decoded.class, r, r.toString()).message();
        assertEquals("map", m.at("header.frame_id"));
        assertEquals(-2.25, m.number("pose.position.y"));
        assertEquals(0.7071067811865476, m.number("pose.orientation.w"));
    }

    @Test
    void idlTypedefsSequencesBoundsArraysAndConstants() {
        MessageDefinition d = parsed("test_msgs/msg/Every", "ros2idl", """
                module test_msgs {
                  module msg {
                    module Every_Constants {
                      const uint8 ONE = 1;
                      const string NAME = "every";
                      const int16 NEGATIVE = -3;
                    };
                    typedef double double__9[9];
                    typedef test_msgs::msg::Item Item__3[3];
                    struct Item { octet o; };
                    struct Every {
                      boolean b; char c; wstring w; short s; unsigned short us; long l; unsigned long ul;
                      long long ll; unsigned long long ull; float f; double d; int8 i8; uint64 u64;
                      string<5> bounded; double__9 covariance; sequence<int16> shorts; sequence<uint64, 4> longs;
                      sequence<string<3>> names; float floats[2]; Item__3 items; sequence<Item> list, other;
                    };
                  };
                };
                """);
        assertEquals(List.of("bool b", "char c", "wstring w", "int16 s", "uint16 us", "int32 l", "uint32 ul",
                "int64 ll", "uint64 ull", "float32 f", "float64 d", "int8 i8", "uint64 u64", "string<=5 bounded",
                "float64[9] covariance", "int16[] shorts", "uint64[<=4] longs", "string<=3[] names", "float32[2] floats",
                "test_msgs/msg/Item[3] items", "test_msgs/msg/Item[] list", "test_msgs/msg/Item[] other"),
                shapes(d.root()));
        assertEquals(List.of(new MessageType.Constant(Primitive.UINT8, "ONE", "1"),
                new MessageType.Constant(Primitive.STRING, "NAME", "\"every\""),
                new MessageType.Constant(Primitive.INT16, "NEGATIVE", "-3")), d.root().constants());
    }

    @Test
    void idlErrorsNameTheLine() {
        DefinitionResult.Refused e = refused("a/msg/B", "ros2idl", "module a {\n  module msg {\n    enum Colour { RED };\n");
        assertEquals("line 3: enum types are not supported", e.reason());
        assertEquals("line 2: the type a::msg::Nope of n is not defined in the schema",
                refused("a/msg/B", "ros2idl", "module a { module msg { struct B {\n Nope n; }; }; };").reason());
        assertEquals("line 2: the schema ends inside a module ('}' missing)",
                refused("a/msg/B", "ros2idl", "module a {\n struct B { int32 x; };\n").reason());
        assertEquals("line 1: '}' where ';' was expected",
                refused("a/msg/B", "ros2idl", "module a { module msg { struct B { int32 x }; }; };").reason());
    }
}
