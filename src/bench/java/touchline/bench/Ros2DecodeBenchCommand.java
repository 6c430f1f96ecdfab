package touchline.bench;

import com.google.protobuf.ByteString;
import com.google.protobuf.InvalidProtocolBufferException;
import com.google.protobuf.Message;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.bench.ros2.Ros2Bench;
import touchline.protocol.ros2.CdrDecoder;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.DefinitionParser;
import touchline.protocol.ros2.DefinitionResult;
import touchline.protocol.ros2.MessageDecoder;
import touchline.protocol.ros2.Ros2Sources;
import touchline.protocol.ros2.RosMessage;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;

/**
 * CDR decoding by a run-time definition (issue 39) against protobuf-java's generated parser on
 * the same content, alternating in one run: the typical mix of a ROS 2 robot (an
 * {@code rcl_interfaces/msg/Log}, a {@code geometry_msgs/msg/PoseStamped}, a
 * {@code sensor_msgs/msg/JointState} of 24 joints, a {@code sensor_msgs/msg/CompressedImage} of a
 * 640×480 JPEG's size), one message of each in turn. The CDR bytes are the golden vectors
 * {@code mcap_ros2} made (the image's data grown to {@link #JPEG_BYTES}); the protobuf messages
 * are built from what the CDR decoder read, so both decode the same values. One thread, no I/O.
 * Budget: CDR ≤ 1.5 × protobuf's time per message.
 */
@Command(name = "cdr", mixinStandardHelpOptions = true,
        description = "Nanoseconds per message: ROS 2 CDR decoding by its definition against protobuf-java on the same content.")
final class Ros2DecodeBenchCommand implements Callable<Integer> {

    /** A 640×480 JPEG of a robot's camera at quality 75–85 is 30–60 KB. */
    static final int JPEG_BYTES = 45_000;

    @Option(names = "--rounds", defaultValue = "5", description = "alternating rounds (default ${DEFAULT-VALUE})")
    int rounds;

    @Option(names = "--seconds", defaultValue = "2", description = "seconds per measurement (default ${DEFAULT-VALUE})")
    double seconds;

    private static final String[] TYPES = {"rcl_interfaces/msg/Log", "geometry_msgs/msg/PoseStamped",
            "sensor_msgs/msg/JointState", "sensor_msgs/msg/CompressedImage"};

    private final List<MessageDecoder> decoders = new ArrayList<>();
    private final List<byte[]> cdr = new ArrayList<>();
    private final List<byte[]> protobuf = new ArrayList<>();
    private long sink;
    private int next;

    @Override
    public Integer call() throws Exception {
        DefinitionParser parser = new DefinitionParser();
        for (String type : TYPES) {
            DefinitionResult r = parser.parse(type, "ros2msg", Ros2Sources.definition(type));
            MessageDecoder decoder = new CdrDecoder(((DefinitionResult.Parsed) r).definition());
            byte[] bytes = golden(type.replace('/', '.') + ".cdr");
            if (type.endsWith("CompressedImage")) {
                bytes = withImageData(bytes, JPEG_BYTES);
            }
            RosMessage m = ((DecodeResult.Decoded) decoder.decode(bytes)).message();
            decoders.add(decoder);
            cdr.add(bytes);
            protobuf.add(asProtobuf(type, m).toByteArray());
        }
        System.out.printf("cdr benchmark: %d rounds x %.1f s each; mix of %s; CDR %s bytes, protobuf %s bytes%n",
                rounds, seconds, String.join(", ", TYPES), cdr.stream().map(b -> Integer.toString(b.length)).toList(),
                protobuf.stream().map(b -> Integer.toString(b.length)).toList());
        for (int warm = 0; warm < 3; warm++) {
            perMessage(this::protobufOne);
            perMessage(this::cdrOne);
        }
        List<Double> ratios = new ArrayList<>();
        for (int round = 1; round <= rounds; round++) {
            double pb = perMessage(this::protobufOne);
            double c = perMessage(this::cdrOne);
            ratios.add(c / pb);
            System.out.printf("round %d: protobuf-java %.0f ns, CDR %.0f ns per message: CDR takes %.2f x protobuf's time%n",
                    round, pb, c, c / pb);
        }
        // the mix's time is mostly the image's copy: each type alone as well, so the small ones are seen
        for (int type = 0; type < TYPES.length; type++) {
            int only = type;
            double pb = perMessage(() -> {
                next = only;
                protobufOne();
            });
            double c = perMessage(() -> {
                next = only;
                cdrOne();
            });
            System.out.printf("%s alone: protobuf-java %.0f ns, CDR %.0f ns: %.2f x%n", TYPES[type], pb, c, c / pb);
        }
        double median = IngestBenchCommand.median(ratios);
        System.out.printf("median: CDR takes %.2f x protobuf's time (budget 1.5: %s) (checksum %d)%n", median,
                median <= 1.5 ? "met" : "NOT met", sink);
        return 0;
    }

    private void cdrOne() {
        int i = next++ & 3;
        if (decoders.get(i).decode(cdr.get(i)) instanceof DecodeResult.Decoded d) {
            sink += d.message().fieldCount();
        }
    }

    private void protobufOne() {
        int i = next++ & 3;
        byte[] b = protobuf.get(i);
        try {
            Message m = switch (i) {
                case 0 -> Ros2Bench.Log.parseFrom(b);
                case 1 -> Ros2Bench.PoseStamped.parseFrom(b);
                case 2 -> Ros2Bench.JointState.parseFrom(b);
                default -> Ros2Bench.CompressedImage.parseFrom(b);
            };
            sink += m.getDescriptorForType().getFields().size();
        } catch (InvalidProtocolBufferException e) {
            throw new IllegalStateException(e);
        }
    }

    private double perMessage(Runnable one) {
        return TagBenchCommand.nanosPerCall(one, seconds);
    }

    private static byte[] golden(String name) throws IOException {
        try (InputStream in = Ros2DecodeBenchCommand.class.getResourceAsStream("/ros2/cdr/" + name)) {
            if (in == null) {
                throw new IOException("no golden vector " + name + " (the test resources are not on the class path)");
            }
            return in.readAllBytes();
        }
    }

    /** The CompressedImage vector with its data (its last field: a uint32 length, then the bytes) replaced by {@code n} bytes. */
    private static byte[] withImageData(byte[] golden, int n) {
        ByteBuffer g = ByteBuffer.wrap(golden).order(ByteOrder.LITTLE_ENDIAN);
        int lengthAt = -1;
        for (int at = 4; at + 4 <= golden.length; at += 4) {
            if (g.getInt(at) == golden.length - at - 4) {
                lengthAt = at;
                break;
            }
        }
        byte[] data = new byte[n];
        new Random(39).nextBytes(data);
        ByteBuffer out = ByteBuffer.allocate(lengthAt + 4 + n).order(ByteOrder.LITTLE_ENDIAN);
        out.put(golden, 0, lengthAt).putInt(n).put(data);
        return out.array();
    }

    private static Message asProtobuf(String type, RosMessage m) {
        return switch (type) {
            case "rcl_interfaces/msg/Log" -> Ros2Bench.Log.newBuilder().setStamp(time((RosMessage) m.get("stamp")))
                    .setLevel((Integer) m.get("level")).setName((String) m.get("name")).setMsg((String) m.get("msg"))
                    .setFile((String) m.get("file")).setFunction((String) m.get("function"))
                    .setLine((int) (long) (Long) m.get("line")).build();
            case "geometry_msgs/msg/PoseStamped" -> Ros2Bench.PoseStamped.newBuilder()
                    .setHeader(header((RosMessage) m.get("header")))
                    .setPose(Ros2Bench.Pose.newBuilder()
                            .setPosition(Ros2Bench.Point.newBuilder().setX(m.number("pose.position.x"))
                                    .setY(m.number("pose.position.y")).setZ(m.number("pose.position.z")))
                            .setOrientation(Ros2Bench.Quaternion.newBuilder().setX(m.number("pose.orientation.x"))
                                    .setY(m.number("pose.orientation.y")).setZ(m.number("pose.orientation.z"))
                                    .setW(m.number("pose.orientation.w")))).build();
            case "sensor_msgs/msg/JointState" -> {
                Ros2Bench.JointState.Builder b = Ros2Bench.JointState.newBuilder()
                        .setHeader(header((RosMessage) m.get("header")))
                        .addAllName(List.of((String[]) m.get("name")));
                for (double v : (double[]) m.get("position")) {
                    b.addPosition(v);
                }
                for (double v : (double[]) m.get("velocity")) {
                    b.addVelocity(v);
                }
                for (double v : (double[]) m.get("effort")) {
                    b.addEffort(v);
                }
                yield b.build();
            }
            default -> Ros2Bench.CompressedImage.newBuilder().setHeader(header((RosMessage) m.get("header")))
                    .setFormat((String) m.get("format")).setData(ByteString.copyFrom((byte[]) m.get("data"))).build();
        };
    }

    private static Ros2Bench.Header header(RosMessage h) {
        return Ros2Bench.Header.newBuilder().setStamp(time((RosMessage) h.get("stamp")))
                .setFrameId((String) h.get("frame_id")).build();
    }

    private static Ros2Bench.Time time(RosMessage t) {
        return Ros2Bench.Time.newBuilder().setSec((Integer) t.get("sec")).setNanosec((int) (long) (Long) t.get("nanosec"))
                .build();
    }
}
