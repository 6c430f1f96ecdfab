package touchline.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The independent Python {@code mcap} package as a test's second opinion on a file. A missing
 * package skips the test on a developer's machine and fails it under CI ({@code CI=true}),
 * so a missing install step never passes as a green run that checked nothing.
 */
public final class PythonMcap {

    private PythonMcap() {
    }

    /** Skips (or under CI fails) the test unless python3 can import every module. */
    public static void require(String... modules) {
        String imports = "import " + String.join(", ", modules);
        boolean present;
        try {
            Process p = new ProcessBuilder("python3", "-c", imports).redirectErrorStream(true).start();
            present = p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            present = false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            present = false;
        }
        Requirement.require(present,
                "python3 cannot '" + imports + "' (./touchline installs them: pip install mcap zstandard lz4)");
    }

    /** Runs {@code script} with {@code args} as sys.argv[1..]; returns its output, fails the test if it fails. */
    public static String run(String script, Object... args) throws IOException, InterruptedException {
        Process p = start(script, args);
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "python did not finish");
        if (p.exitValue() != 0) {
            throw new AssertionError("python failed: " + text);
        }
        return text;
    }

    /** True when {@code script} fails on {@code args} (e.g. the reader refuses an unfinished file). */
    public static boolean fails(String script, Object... args) throws IOException, InterruptedException {
        Process p = start(script, args);
        p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "python did not finish");
        return p.exitValue() != 0;
    }

    private static Process start(String script, Object... args) throws IOException {
        List<String> command = new ArrayList<>(List.of("python3", "-c", script));
        for (Object a : args) {
            command.add(a.toString());
        }
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        p.getOutputStream().close();
        return p;
    }

    /**
     * Reads {@code file} through its summary and indexes (the seeking reader, as index-based
     * tools such as the Rust crate's indexed reader do) and checks every index against the
     * records it points to. Prints: messages read through the index, the statistics' message
     * count, chunk indexes, chunk indexes that match their chunk, message-index entries that
     * point to a message of their channel and time (in log-time order), summary offsets that
     * point to a group of their opcode.
     */
    public static final String INDEXED_READ = """
            import io, sys
            from mcap.reader import make_reader, SeekingReader
            from mcap.records import Chunk, MessageIndex, Message, Footer, SummaryOffset
            from mcap.stream_reader import StreamReader, get_chunk_data_stream
            from mcap.data_stream import ReadDataStream
            def record_at(f, offset):
                f.seek(offset)
                return next(StreamReader(f, skip_magic=True, emit_chunks=True, validate_crcs=True).records)
            with open(sys.argv[1], 'rb') as f:
                r = make_reader(f, validate_crcs=True)
                assert isinstance(r, SeekingReader), type(r)
                s = r.get_summary()
                n = sum(1 for _ in r.iter_messages(log_time_order=True))
                consistent = 0
                good_entries = 0
                for ci in s.chunk_indexes:
                    chunk = record_at(f, ci.chunk_start_offset)
                    assert isinstance(chunk, Chunk), chunk
                    if (len(chunk.data) == ci.compressed_size and chunk.uncompressed_size == ci.uncompressed_size
                            and chunk.compression == ci.compression
                            and chunk.message_start_time == ci.message_start_time
                            and chunk.message_end_time == ci.message_end_time):
                        consistent += 1
                    stream, length = get_chunk_data_stream(chunk, validate_crc=True)
                    data = stream._stream.getvalue() if hasattr(stream, '_stream') else None
                    for channel_id, offset in ci.message_index_offsets.items():
                        mi = record_at(f, offset)
                        assert isinstance(mi, MessageIndex) and mi.channel_id == channel_id, mi
                        times = [t for t, _ in mi.records]
                        assert times == sorted(times), 'message index not in log-time order'
                        for t, at in mi.records:
                            body = ReadDataStream(io.BytesIO(data[at:]))
                            assert body.read1() == 5, 'not a message at offset %d' % at
                            m = Message.read(body, body.read8())
                            if m.channel_id == channel_id and m.log_time == t and ci.message_start_time <= t <= ci.message_end_time:
                                good_entries += 1
                f.seek(-8 - 20 - 9, io.SEEK_END)
                footer = next(StreamReader(f, skip_magic=True).records)
                assert isinstance(footer, Footer), footer
                offsets_ok = 0
                f.seek(footer.summary_offset_start)
                for rec in StreamReader(f, skip_magic=True).records:
                    if not isinstance(rec, SummaryOffset):
                        break
                    f2 = open(sys.argv[1], 'rb')
                    f2.seek(rec.group_start)
                    if f2.read(1)[0] == rec.group_opcode:
                        offsets_ok += 1
                    f2.close()
                print(n, s.statistics.message_count, len(s.chunk_indexes), consistent, good_entries, offsets_ok)
            """;

    /**
     * What {@link #INDEXED_READ} prints for a correct file of {@code messages} messages in
     * {@code chunks} chunks with the five summary groups Touchline writes (schemas, channels,
     * chunk indexes, metadata indexes, statistics).
     */
    public static String indexedRead(long messages, long chunks) {
        return messages + " " + messages + " " + chunks + " " + chunks + " " + messages + " 5";
    }
}
