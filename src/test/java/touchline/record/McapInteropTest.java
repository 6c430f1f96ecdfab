package touchline.record;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.transport.Envelope;

import java.nio.file.Path;
import java.util.List;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.testing.PythonMcap;

/** The recording opens with the independent Python {@code mcap} reader (skipped when it is missing; a failure under CI). */
@Tag("interop")
class McapInteropTest {

    @TempDir
    Path dir;

    @Test
    void pythonMcapReadsEveryMessageAndTopic() throws Exception {
        PythonMcap.require("mcap");
        List<Envelope> sent = RecordingFixture.team(3, 20);
        Path file = dir.resolve("interop.mcap");
        RecordingFixture.write(file, sent, new EnvelopeWriter.Options(0, 0, 16 * 1024, List.of()));
        String out = PythonMcap.run("""
                import sys
                from mcap.reader import make_reader
                with open(sys.argv[1], 'rb') as f:
                    r = make_reader(f, validate_crcs=True)
                    s = r.get_summary()
                    n = sum(1 for _ in r.iter_messages())
                    topics = sorted({c.topic for c in s.channels.values()})
                    print(n, s.statistics.message_count, len(s.chunk_indexes) > 1)
                    print(','.join(topics))
                """, file);
        String[] lines = out.split("\n");
        assertEquals(sent.size() + " " + sent.size() + " True", lines[lines.length - 2]);
        TreeSet<String> topics = new TreeSet<>(List.of(lines[lines.length - 1].split(",")));
        assertTrue(topics.containsAll(List.of("/robot/1/status", "/robot/3/debugPlot", "/gc/hl12", "/nao/out/rpc",
                "/robot/2/out/debugOptionRequest", "/robot/1/malformed", "/link/nao-online")), topics.toString());
    }

    @Test
    void pythonProtobufSupportDecodesAStatus() throws Exception {
        PythonMcap.require("mcap_protobuf");
        Path file = dir.resolve("pb.mcap");
        RecordingFixture.write(file, RecordingFixture.team(1, 2), EnvelopeWriter.Options.defaults());
        String out = PythonMcap.run("""
                import sys
                from mcap.reader import make_reader
                from mcap_protobuf.decoder import DecoderFactory
                with open(sys.argv[1], 'rb') as f:
                    r = make_reader(f, decoder_factories=[DecoderFactory()])
                    for schema, channel, message, decoded in r.iter_decoded_messages(topics=['/robot/1/status']):
                        print(schema.name, decoded.robotID, 'goalie' in str(decoded))
                        break
                """, file);
        assertTrue(out.endsWith("fumanoid.Message 1 True"), out);
    }

    /** A robot's datagram with a team key's trailer: still a protobuf message to another tool. */
    @Test
    void pythonProtobufSupportDecodesATaggedStatus() throws Exception {
        PythonMcap.require("mcap_protobuf");
        touchline.security.MessageTag tag = new touchline.security.MessageTag(new touchline.security.TeamKey(new byte[32]));
        List<touchline.transport.Envelope> sent = new java.util.ArrayList<>();
        long counter = 1;
        for (touchline.transport.Envelope e : RecordingFixture.team(1, 2)) {
            sent.add(e.message() == null ? e : new touchline.transport.Envelope(e.timeMicros(), e.direction(), e.channel(),
                    e.peer(), e.robotId(), e.kind(), e.message(),
                    tag.append(touchline.security.MessageTag.FROM_ROBOT, e.robotId(), counter++, e.raw()), null,
                    touchline.transport.Origin.LIVE, touchline.security.Authenticity.VERIFIED));
        }
        Path file = dir.resolve("tagged.mcap");
        RecordingFixture.write(file, sent, EnvelopeWriter.Options.defaults());
        String out = PythonMcap.run("""
                import sys
                from mcap.reader import make_reader
                from mcap_protobuf.decoder import DecoderFactory
                with open(sys.argv[1], 'rb') as f:
                    r = make_reader(f, decoder_factories=[DecoderFactory()])
                    for schema, channel, message, decoded in r.iter_decoded_messages(topics=['/robot/1/status']):
                        print(channel.message_encoding, schema.name, decoded.robotID, 'goalie' in str(decoded))
                        break
                """, file);
        assertTrue(out.endsWith("protobuf fumanoid.Message 1 True"), out);
    }
}
