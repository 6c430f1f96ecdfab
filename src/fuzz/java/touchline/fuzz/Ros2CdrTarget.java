package touchline.fuzz;

import touchline.protocol.ros2.CdrDecoder;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.DefinitionParser;
import touchline.protocol.ros2.DefinitionResult;
import touchline.protocol.ros2.MessageDefinition;
import touchline.protocol.ros2.Ros2Sources;
import touchline.protocol.ros2.RosMessage;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

/**
 * A CDR message from outside, decoded by a real ROS 2 definition (the first byte chooses which:
 * the common_interfaces types the tests use, and an IDL type with every primitive and shape). It
 * decodes or is refused with a reason, never throws, and what decodes renders within its caps
 * and enumerates its numbers.
 */
final class Ros2CdrTarget implements FuzzTarget {

    static final List<String> TYPES = List.of("rcl_interfaces/msg/Log", "geometry_msgs/msg/PoseStamped",
            "sensor_msgs/msg/JointState", "sensor_msgs/msg/Image", "sensor_msgs/msg/CompressedImage",
            "tf2_msgs/msg/TFMessage", "visualization_msgs/msg/MarkerArray", "diagnostic_msgs/msg/DiagnosticArray",
            "geometry_msgs/msg/Pose2D");

    /** Every primitive and shape, in rosidl's IDL form. */
    static final String IDL = """
            module fuzz_msgs {
              module msg {
                module Every_Constants {
                  const uint8 ONE = 1;
                };
                typedef double double__3[3];
                struct Inner {
                  wstring w;
                  sequence<string<8>, 2> names;
                };
                struct Every {
                  boolean b; octet o; char c; int8 i8; uint8 u8; int16 i16; uint16 u16;
                  int32 i32; uint32 u32; int64 i64; uint64 u64; float f32; double f64;
                  string s; string<5> bounded; double__3 fixed; sequence<int16> shorts;
                  sequence<uint64, 4> longs; sequence<boolean> flags; float floats[2];
                  sequence<fuzz_msgs::msg::Inner> inners; Inner one;
                };
              };
            };
            """;

    private final List<CdrDecoder> decoders = new ArrayList<>();

    Ros2CdrTarget() {
        DefinitionParser parser = new DefinitionParser();
        for (String t : TYPES) {
            decoders.add(new CdrDecoder(parsed(parser.parse(t, "ros2msg", Ros2Sources.definition(t)))));
        }
        decoders.add(new CdrDecoder(parsed(parser.parse("fuzz_msgs/msg/Every", "ros2idl", IDL))));
    }

    private static MessageDefinition parsed(DefinitionResult r) {
        if (r instanceof DefinitionResult.Parsed p) {
            return p.definition();
        }
        throw new IllegalStateException(r.toString());
    }

    @Override
    public String name() {
        return "ros2-cdr";
    }

    @Override
    public void accept(byte[] input) {
        if (input.length == 0) {
            return;
        }
        CdrDecoder decoder = decoders.get((input[0] & 0xFF) % decoders.size());
        DecodeResult r = decoder.decode(input, 1, input.length - 1);
        if (r instanceof DecodeResult.Undecodable u) {
            FuzzTarget.check(!u.reason().isBlank(), "refused without a reason");
            return;
        }
        RosMessage m = ((DecodeResult.Decoded) r).message();
        FuzzTarget.check(m.line(300).length() <= 300, "a line over its cap");
        FuzzTarget.check(m.text(2000).length() <= 2000, "a text over its cap");
        for (String path : m.numericPaths()) {
            FuzzTarget.check(!Double.isNaN(m.number(path)) || m.at(path) instanceof Float
                    || m.at(path) instanceof Double, "an enumerated path " + path + " that names no number");
        }
    }

    @Override
    public List<byte[]> seeds() {
        List<byte[]> out = new ArrayList<>();
        for (int i = 0; i < TYPES.size(); i++) {
            out.add(withSelector(i, golden(TYPES.get(i).replace('/', '.') + ".cdr")));
        }
        out.add(withSelector(1, golden("PoseStamped.be.cdr")));
        return out;
    }

    static byte[] golden(String name) {
        try (InputStream in = Ros2CdrTarget.class.getResourceAsStream("/ros2/cdr/" + name)) {
            if (in == null) {
                throw new IllegalStateException("no golden vector " + name);
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static byte[] withSelector(int selector, byte[] message) {
        byte[] out = new byte[message.length + 1];
        out[0] = (byte) selector;
        System.arraycopy(message, 0, out, 1, message.length);
        return out;
    }
}
