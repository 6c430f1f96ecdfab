package touchline.record;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import touchline.testing.PythonMcap;
import touchline.transport.Envelope;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Recordings whose chunks another tool compressed (Foxglove's SDK, Lichtblick and rosbag2
 * write zstd or lz4 by default), or that have no chunks at all, replay completely: the Python
 * {@code mcap} writer re-writes a Touchline recording with zstd chunks, with lz4 chunks and
 * unchunked, and every envelope comes back.
 */
class CompressedRecordingTest {

    /** Copies argv[1] to argv[2], every chunk compressed with argv[3] (ZSTD or LZ4), in small chunks. */
    private static final String REWRITE = """
            import sys
            from mcap.reader import make_reader
            from mcap.writer import Writer, CompressionType
            src, dst, compression = sys.argv[1:4]
            with open(src, 'rb') as f, open(dst, 'wb') as o:
                r = make_reader(f)
                if compression == 'UNCHUNKED':
                    w = Writer(o, use_chunking=False)
                else:
                    w = Writer(o, chunk_size=8 * 1024, compression=CompressionType[compression])
                w.start('touchline', 'python-mcap')
                schemas, channels = {}, {}
                for schema, channel, m in r.iter_messages(log_time_order=False):
                    if channel.id not in channels:
                        sid = 0
                        if schema is not None:
                            if schema.id not in schemas:
                                schemas[schema.id] = w.register_schema(schema.name, schema.encoding, schema.data)
                            sid = schemas[schema.id]
                        channels[channel.id] = w.register_channel(channel.topic, channel.message_encoding, sid,
                                                                  channel.metadata)
                    w.add_message(channels[channel.id], m.log_time, m.data, m.publish_time, m.sequence)
                w.finish()
            with open(dst, 'rb') as f:
                print(sorted({c.compression for c in make_reader(f).get_summary().chunk_indexes}) or 'unchunked')
            """;

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"ZSTD", "LZ4", "UNCHUNKED"})
    void filesOfThePythonWriterReplayCompletely(String compression) throws Exception {
        PythonMcap.require("mcap", "zstandard", "lz4");
        List<Envelope> sent = RecordingFixture.team(3, 10);
        Path ours = dir.resolve("ours.mcap");
        RecordingFixture.write(ours, sent, EnvelopeWriter.Options.defaults());
        Path theirs = dir.resolve(compression + ".mcap");
        String used = PythonMcap.run(REWRITE, ours, theirs, compression);
        boolean chunked = !compression.equals("UNCHUNKED");
        assertEquals(chunked ? "['" + compression.toLowerCase() + "']" : "unchunked", used);
        try (Recording r = Recording.open(theirs)) {
            assertEquals(chunked, r.mcap().chunkCount() > 3, "several chunks, or none");
            assertEquals(sent, RecordingFixture.readAll(r));
            assertTrue(r.problems().isEmpty(), r.problems().toString());
        }
    }
}
