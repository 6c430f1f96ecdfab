package touchline.record;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.cli.ExportCommand;
import touchline.cli.ReplayCommand;
import touchline.model.store.FieldPlot;
import touchline.model.store.PlotStore;
import touchline.protocol.MessageKinds;
import touchline.protocol.ros2.Ros2Sources;
import touchline.protocol.ros2.RosMessage;
import touchline.testing.PythonMcap;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A ROS 2 bag as the Python {@code mcap_ros2} writer makes it with its defaults (zstd chunks of
 * 1 MiB, the ros2 profile): it replays completely through the ROS 2 decoders (every message
 * decoded, values as written), seeks, and exports its numeric fields as CSV. Before issue 39 it
 * replayed 0 envelopes ("ros2msg/cdr: encoding not supported").
 */
@Tag("interop")
class Ros2BagReplayTest {

    static final int N = 200;
    static final long T0 = 1_733_390_000_000_000_000L;
    static final long STEP = 10_000_000L; // 10 ms

    /** argv: out.mcap, directory of TYPE.msg definitions, N. */
    static final String WRITE = """
            import os, sys
            from mcap_ros2.writer import Writer
            out, d, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
            def schema(w, name):
                return w.register_msgdef(name, open(os.path.join(d, name.replace('/', '.') + '.msg')).read())
            with open(out, 'wb') as f:
                w = Writer(f)
                log = schema(w, 'rcl_interfaces/msg/Log')
                pose = schema(w, 'geometry_msgs/msg/PoseStamped')
                joints = schema(w, 'sensor_msgs/msg/JointState')
                image = schema(w, 'sensor_msgs/msg/CompressedImage')
                tf = schema(w, 'tf2_msgs/msg/TFMessage')
                for i in range(n):
                    t = %d + i * %d
                    stamp = {'sec': t // 1000000000, 'nanosec': t %% 1000000000}
                    header = {'stamp': stamp, 'frame_id': 'map'}
                    w.write_message('/pose', pose, {'header': header, 'pose': {'position': {'x': i * 0.01, 'y': -i, 'z': 0.0},
                        'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}}, log_time=t, sequence=i)
                    w.write_message('/joint_states', joints, {'header': header, 'name': ['j%%d' %% k for k in range(24)],
                        'position': [i + k / 100 for k in range(24)], 'velocity': [0.0] * 24, 'effort': [k * 1.0 for k in range(24)]},
                        log_time=t + 1, sequence=i)
                    w.write_message('/tf', tf, {'transforms': [{'header': header, 'child_frame_id': 'base_link',
                        'transform': {'translation': {'x': 1.0, 'y': 2.0, 'z': i * 1.0},
                                      'rotation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}}]}, log_time=t + 2, sequence=i)
                    if i %% 10 == 0:
                        w.write_message('/rosout', log, {'stamp': stamp, 'level': 20, 'name': 'walker', 'msg': 'step %%d' %% i,
                            'file': 'walk.cpp', 'function': 'step', 'line': 42}, log_time=t + 3, sequence=i)
                        w.write_message('/camera/compressed', image, {'header': header, 'format': 'jpeg',
                            'data': bytes([0xff, 0xd8]) + os.urandom(60000) + bytes([0xff, 0xd9])}, log_time=t + 4, sequence=i)
                w.finish()
            """.formatted(T0, STEP);

    static final int TOTAL = 3 * N + 2 * (N / 10);

    @TempDir
    static Path dir;
    static Path bag;

    @BeforeAll
    static void write() throws Exception {
        PythonMcap.require("mcap_ros2", "zstandard");
        for (String t : List.of("rcl_interfaces/msg/Log", "geometry_msgs/msg/PoseStamped", "sensor_msgs/msg/JointState",
                "sensor_msgs/msg/CompressedImage", "tf2_msgs/msg/TFMessage")) {
            Files.writeString(dir.resolve(t.replace('/', '.') + ".msg"), Ros2Sources.definition(t));
        }
        bag = dir.resolve("bag.mcap");
        PythonMcap.run(WRITE, bag, dir, N);
    }

    @Test
    void theWritersDefaultBagReplaysCompletelyDecoded() throws Exception {
        try (Recording r = Recording.open(bag)) {
            assertTrue(r.mcap().chunkCount() >= 2, "zstd chunks of 1 MiB: " + r.mcap().chunkCount());
            List<Envelope> all = RecordingFixture.readAll(r);
            assertEquals(TOTAL, all.size());
            assertTrue(all.stream().allMatch(e -> e.channel() == Channel.FOREIGN && e.ros() != null && e.error() == null),
                    "every message decoded");
            assertEquals(List.of(), r.notes().skipped());
            assertEquals(List.of(), r.problems());
            Map<String, List<Envelope>> byTopic = all.stream().collect(Collectors.groupingBy(Envelope::kind));
            RosMessage pose = byTopic.get("/pose").get(150).ros();
            assertEquals("geometry_msgs/msg/PoseStamped", pose.typeName());
            assertEquals(1.5, pose.number("pose.position.x"), 1e-12);
            assertEquals(-150.0, pose.number("pose.position.y"));
            assertEquals((T0 + 150 * STEP) / 1000, byTopic.get("/pose").get(150).timeMicros());
            RosMessage joints = byTopic.get("/joint_states").get(7).ros();
            assertEquals(7.23, joints.number("position[23]"), 1e-12);
            assertEquals("j23", ((String[]) joints.get("name"))[23]);
            assertEquals(199.0, byTopic.get("/tf").get(199).ros().number("transforms[0].transform.translation.z"));
            assertEquals("step 190", byTopic.get("/rosout").get(19).ros().get("msg"));
            assertEquals(60004, ((byte[]) byTopic.get("/camera/compressed").get(3).ros().get("data")).length);
            assertEquals(List.of(), r.events(), "a bag has no game events");
        }
    }

    @Test
    void numericFieldsPlotByPath() throws Exception {
        try (Recording r = Recording.open(bag)) {
            FieldPlot plot = new FieldPlot(new MessageKinds(), 1000, T0 / 1000);
            List<Envelope> all = RecordingFixture.readAll(r);
            plot.accept(all.get(0));
            assertTrue(plot.paths("position.x").contains("/pose:pose.position.x"), plot.paths("position").toString());
            assertTrue(plot.add(Envelope.NO_ROBOT, "/pose:pose.position.x"));
            assertTrue(plot.add(Envelope.NO_ROBOT, "/pose:pose.position.y"));
            all.forEach(plot::accept);
            assertTrue(plot.paths("/joint_states:position[23]").contains("/joint_states:position[23]"));
            List<PlotStore.SeriesData> data = plot.snapshot();
            assertEquals(List.of("/pose:pose.position.x", "/pose:pose.position.y"),
                    data.stream().map(PlotStore.SeriesData::name).toList());
            assertEquals(N, data.get(0).count());
            assertEquals(1.5, data.get(0).y()[150], 1e-12);
            assertEquals(-150.0, data.get(1).y()[150]);
            assertEquals(1.5, data.get(0).x()[150], 1e-9, "seconds since the plot's origin");
        }
    }

    @Test
    void seekingLandsOnTheMessageOfThatTime() throws Exception {
        try (Recording r = Recording.open(bag)) {
            long at = (T0 + 120 * STEP) / 1000;
            Envelope first = r.cursor(at).next();
            assertEquals(at, first.timeMicros());
            assertEquals("/pose", first.kind());
            assertEquals(1.2, first.ros().number("pose.position.x"), 1e-12);
        }
    }

    @Test
    void numericFieldsExportAsCsv() throws Exception {
        String[] out = run(new ExportCommand(), bag.toString(), "--csv", "--channel", "/joint_states");
        List<String> lines = out[0].lines().toList();
        assertEquals(1 + N, lines.size(), out[1]);
        List<String> header = List.of(lines.get(0).split(","));
        assertEquals(List.of("time", "log_time_ns", "header.stamp.sec", "header.stamp.nanosec", "position[0]"),
                header.subList(0, 5));
        assertEquals(2 + 2 + 3 * 24, header.size(), "no column for the names (text) of the joints");
        List<String> row = List.of(lines.get(1 + 7).split(","));
        assertEquals("0.070000001", row.get(0));
        assertEquals(Long.toString(T0 + 7 * STEP + 1), row.get(1));
        assertEquals("7.23", row.get(header.indexOf("position[23]")));
        assertEquals("23", row.get(header.indexOf("effort[23]")));

        String[] pose = run(new ExportCommand(), bag.toString(), "--csv", "--channel", "/pose");
        assertTrue(pose[0].lines().skip(1 + 150).findFirst().orElseThrow().contains(",1.5,-150,0,0,0,0,1"), pose[0]);
    }

    @Test
    void replayPrintsEveryMessageAsText() {
        String[] out = run(new ReplayCommand(), bag.toString(), "--headless");
        assertEquals(TOTAL, out[0].lines().count(), out[1]);
        assertTrue(out[0].contains("/rosout rcl_interfaces/msg/Log {stamp: {sec: 1733390001, nanosec: 900000000},"
                + " level: 20, name: \"walker\", msg: \"step 190\""), out[0].lines().filter(l -> l.contains("step 190"))
                .findFirst().orElse(out[0].substring(0, 400)));
        assertTrue(out[0].contains("data: <60004 bytes>"));
        assertTrue(!out[1].contains("skipped"), out[1]);
    }

    private static String[] run(Object command, String... args) {
        return OtherToolsRecordingTest.run(command, args);
    }
}
