package touchline.record;

import com.google.protobuf.Message;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;
import touchline.cli.ExportCommand;
import touchline.cli.ReplayCommand;
import touchline.proto.Fumanoid;
import touchline.testing.PythonMcap;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Files another tool wrote (here the Python {@code mcap} writer and {@code mcap-protobuf-support}):
 * attachments and metadata records, several schemas (Touchline's own protobuf type, a protobuf
 * type Touchline does not know whose descriptor set is in the file, JSON, ros2msg/cdr,
 * flatbuffer, a channel without a schema), tiny and large chunks, unchunked, zstd and lz4.
 * What can be shown plays; the rest is skipped and counted by channel with the reason, the
 * same notes for {@code replay}, {@code replay --info}, {@code export} and the window.
 */
@Tag("interop")
class OtherToolsRecordingTest {

    static final int N = 40;

    /**
     * argv: out, layout (NONE-64, NONE-10000000, ZSTD-4096, LZ4-4096, UNCHUNKED, or ZSTD / LZ4 for the
     * writer's default chunk size), fumanoid FDS, fumanoid payload, N.
     */
    private static final String WRITE = """
            import json, sys
            from google.protobuf import descriptor_pb2, descriptor_pool, message_factory
            from mcap.writer import Writer, CompressionType
            from mcap_protobuf.schema import build_file_descriptor_set
            out, layout, fds_path, payload_path, n = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
            # a protobuf type Touchline has never seen, with a nested message
            f = descriptor_pb2.FileDescriptorProto(name='other/pose.proto', package='other', syntax='proto3')
            pose = f.message_type.add(name='Pose')
            point = pose.nested_type.add(name='Point')
            point.field.add(name='x', number=1, type=descriptor_pb2.FieldDescriptorProto.TYPE_DOUBLE)
            point.field.add(name='y', number=2, type=descriptor_pb2.FieldDescriptorProto.TYPE_DOUBLE)
            pose.field.add(name='frame', number=1, type=descriptor_pb2.FieldDescriptorProto.TYPE_STRING)
            pose.field.add(name='at', number=2, type=descriptor_pb2.FieldDescriptorProto.TYPE_MESSAGE,
                           type_name='.other.Pose.Point')
            pool = descriptor_pool.DescriptorPool()
            pool.Add(f)
            Pose = message_factory.GetMessageClass(pool.FindMessageTypeByName('other.Pose'))
            Point = message_factory.GetMessageClass(pool.FindMessageTypeByName('other.Pose.Point'))
            kind, size = (layout.split('-') + ['0'])[:2]
            with open(out, 'wb') as o:
                if kind == 'UNCHUNKED':
                    w = Writer(o, use_chunking=False)
                elif size == '0':
                    w = Writer(o, compression=CompressionType[kind])
                else:
                    w = Writer(o, chunk_size=int(size), compression=CompressionType[kind])
                w.start('', 'python-mcap')
                w.add_attachment(create_time=1, log_time=2, name='calibration.yaml', media_type='application/yaml',
                                 data=b'camera: {fx: 520.0}\\n' * 10)
                w.add_metadata('match', {'team': 'FUmanoids', 'field': 'B'})
                fum = w.register_schema('fumanoid.Message', 'protobuf', open(fds_path, 'rb').read())
                other = w.register_schema('other.Pose.Point', 'protobuf',
                                          build_file_descriptor_set(Point).SerializeToString())
                other_pose = w.register_schema('other.Pose', 'protobuf', build_file_descriptor_set(Pose).SerializeToString())
                js = w.register_schema('Score', 'jsonschema', b'{"type": "object"}')
                ros = w.register_schema('std_msgs/msg/String', 'ros2msg', b'string data')
                fb = w.register_schema('Monster', 'flatbuffer', b'\\x00\\x01')
                channels = {
                    'fumanoid': w.register_channel('/their/status', 'protobuf', fum),
                    'pose': w.register_channel('/pose', 'protobuf', other_pose),
                    'json': w.register_channel('/score', 'json', js),
                    'cdr': w.register_channel('/chatter', 'cdr', ros),
                    'fb': w.register_channel('/monster', 'flatbuffer', fb),
                    'bare': w.register_channel('/bare', 'protobuf', 0),
                }
                status = open(payload_path, 'rb').read()
                for i in range(n):
                    t = 1_700_000_000_000_000_000 + i * 10_000_000
                    p = Pose(frame='field', at=Point(x=i, y=-i)).SerializeToString()
                    data = {'fumanoid': status, 'pose': p, 'json': json.dumps({'home': i, 'away': 0}).encode(),
                            'cdr': b'\\x00\\x01\\x00\\x00\\x06\\x00\\x00\\x00hello\\x00',
                            # valid protobuf bytes (a Pose): a schemaless channel is still never decoded as one
                            'fb': p, 'bare': status}
                    for k, c in channels.items():
                        w.add_message(c, log_time=t, data=data[k], publish_time=t, sequence=i)
                w.finish()
            """;

    @TempDir
    Path dir;

    private Path written(String layout) throws Exception {
        return written(layout, N);
    }

    private Path written(String layout, int n) throws Exception {
        PythonMcap.require("mcap", "mcap_protobuf", "zstandard", "lz4");
        Path fds = dir.resolve("fumanoid.desc");
        Files.write(fds, SchemaSet.descriptorSet(List.of(Fumanoid.getDescriptor())).toByteArray());
        Envelope status = RecordingFixture.team(1, 1).stream().filter(e -> e.kind().equals("status")).findFirst()
                .orElseThrow();
        Path payload = dir.resolve("status.bin");
        Files.write(payload, status.message().toByteArray());
        Path file = dir.resolve(layout + ".mcap");
        PythonMcap.run(WRITE, file, layout, fds, payload, n);
        return file;
    }

    /**
     * The Python writer with its defaults: 1 MiB chunks, whose LZ4 frames are 64 KiB blocks
     * linked to each other (lz4-java's frame reader refused them: 89 of 9 295 messages played).
     */
    @ParameterizedTest
    @ValueSource(strings = {"LZ4", "ZSTD"})
    void filesWithTheWritersDefaultChunksPlayWhole(String compression) throws Exception {
        int n = 3_000;
        Path file = written(compression, n);
        byte[] bytes = Files.readAllBytes(file);
        java.nio.ByteBuffer chunk = firstChunk(bytes);
        long uncompressed = chunk.getLong(16);
        int nameLength = chunk.getInt(28);
        assertEquals(compression.toLowerCase(java.util.Locale.ROOT),
                new String(bytes, chunk.arrayOffset() + 32, nameLength, java.nio.charset.StandardCharsets.US_ASCII));
        assertTrue(uncompressed >= 1 << 20, "a default chunk of " + uncompressed + " bytes");
        if (compression.equals("LZ4")) {
            int flags = bytes[chunk.arrayOffset() + 32 + nameLength + 8 + 4];
            assertEquals(0, flags & 0x20, "the frame's blocks are linked (block independence flag clear)");
        }
        try (Recording r = Recording.open(file)) {
            assertTrue(r.mcap().chunkCount() >= 2, r.mcap().chunkCount() + " chunks");
            assertEquals(4L * n, RecordingFixture.readAll(r).size());
            assertEquals(List.of(), r.problems());
        }
    }

    /** The content of the file's first chunk record (start time at 0), over the file's bytes. */
    private static java.nio.ByteBuffer firstChunk(byte[] file) {
        for (int at = 8; at < file.length; ) {
            long length = McapSurgery.u64(file, at + 1);
            if (file[at] == McapRecords.CHUNK) {
                return java.nio.ByteBuffer.wrap(file, at + 9, (int) length).slice()
                        .order(java.nio.ByteOrder.LITTLE_ENDIAN);
            }
            at += 9 + (int) length;
        }
        throw new AssertionError("no chunk");
    }

    @ParameterizedTest
    @ValueSource(strings = {"NONE-64", "NONE-10000000", "ZSTD-4096", "LZ4-4096", "UNCHUNKED"})
    void whatCanBeShownPlaysAndTheRestIsSkippedByChannelWithACount(String layout) throws Exception {
        Path file = written(layout);
        try (Recording r = Recording.open(file)) {
            if (layout.equals("NONE-64")) {
                assertTrue(r.mcap().chunkCount() >= N, "a chunk per message: " + r.mcap().chunkCount());
            } else if (layout.equals("NONE-10000000")) {
                assertEquals(1, r.mcap().chunkCount());
            }
            List<Envelope> back = RecordingFixture.readAll(r);
            Map<String, List<Envelope>> byTopic = back.stream().collect(Collectors.groupingBy(Envelope::kind));
            assertEquals(java.util.Set.of("/their/status", "/pose", "/score", "/chatter"), byTopic.keySet());
            assertTrue(back.stream().allMatch(e -> e.channel() == Channel.FOREIGN && e.replayed() == false));
            byTopic.values().forEach(l -> assertEquals(N, l.size()));
            // Touchline's own type, written by another tool: decoded with Touchline's types
            Fumanoid.Message status = assertInstanceOf(Fumanoid.Message.class, byTopic.get("/their/status").get(0).message());
            assertTrue(status.hasExtension(Fumanoid.status), status.toString());
            // a type known only by the descriptor set in the file: rendered by name
            Message pose = byTopic.get("/pose").get(7).message();
            assertEquals("other.Pose", pose.getDescriptorForType().getFullName());
            String text = new touchline.protocol.MessageText().renderLine(pose);
            assertTrue(text.contains("field") && text.contains("7.0") && text.contains("-7.0"), text);
            // JSON: its text kept, its values decoded
            assertEquals("{\"home\": 3, \"away\": 0}", new String(byTopic.get("/score").get(3).raw(),
                    java.nio.charset.StandardCharsets.UTF_8));
            assertEquals(null, byTopic.get("/score").get(3).message());
            assertEquals(3L, byTopic.get("/score").get(3).ros().get("home"));
            // ROS 2 CDR by its ros2msg definition
            assertEquals("std_msgs/msg/String", byTopic.get("/chatter").get(0).ros().typeName());
            assertEquals("hello", byTopic.get("/chatter").get(0).ros().get("data"));

            ReplayNotes notes = r.notes();
            assertTrue(notes.complete());
            assertEquals(List.of("/monster (flatbuffer/flatbuffer: encoding not supported) 40",
                    "/bare (no schema/protobuf: protobuf without a protobuf schema) 40"),
                    notes.skipped().stream().map(Object::toString).toList());
            assertEquals(2L * N, notes.skippedMessages());
            assertEquals(List.of("attachment calibration.yaml (application/yaml, 200 bytes)",
                    "metadata match: team=FUmanoids, field=B"), notes.contents());
            assertTrue(notes.problems().isEmpty(), notes.problems().toString());
            assertEquals(notes.lines(), List.of(notes.skippedLine().orElseThrow()));
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"ZSTD-4096"})
    void replayInfoAndExportSayTheSameNotes(String layout) throws Exception {
        Path file = written(layout);
        String[] replay = run(new ReplayCommand(), file.toString(), "--headless");
        assertEquals(4L * N, replay[0].lines().count(), replay[0]);
        assertTrue(replay[0].contains("/pose") && replay[0].contains("frame: \"field\""), replay[0]);
        assertTrue(replay[0].contains("{away: 0, home: 0}"), replay[0]);
        assertTrue(replay[0].contains("/chatter std_msgs/msg/String {data: \"hello\"}"), replay[0]);
        String skipped = "note: skipped 80 messages of 2 channels:"
                + " /monster (flatbuffer/flatbuffer: encoding not supported) 40, /bare (no schema/protobuf: protobuf"
                + " without a protobuf schema) 40";
        assertTrue(replay[1].contains(skipped), replay[1]);
        assertTrue(replay[1].contains("attachment calibration.yaml (application/yaml, 200 bytes)"), replay[1]);

        String[] info = run(new ReplayCommand(), file.toString(), "--info");
        assertTrue(info[0].contains("channel /chatter (ros2msg std_msgs/msg/String/cdr) 40 messages"), info[0]);
        assertTrue(info[0].contains("attachment calibration.yaml (application/yaml, 200 bytes)"), info[0]);
        assertTrue(info[0].contains("metadata match: team=FUmanoids, field=B"), info[0]);
        assertTrue(info[1].contains(skipped), info[1]);

        String[] export = run(new ExportCommand(), file.toString(), "--robot", "1", "--kind", "debugPlot", "--csv");
        assertTrue(export[1].contains(skipped), export[1]);
        assertTrue(export[1].contains("calibration.yaml") && export[1].contains("a CSV export does not carry"), export[1]);
        assertFalse(export[1].contains("Exception"), export[1]);
    }

    /** Runs a command line; returns {out, err}; fails unless it exits 0. */
    static String[] run(Object command, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine c = new CommandLine(command);
        c.setOut(new PrintWriter(out));
        c.setErr(new PrintWriter(err));
        assertEquals(0, c.execute(args), err.toString());
        return new String[]{out.toString(), err.toString()};
    }
}
