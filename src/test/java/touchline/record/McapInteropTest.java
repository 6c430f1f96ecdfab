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
}
