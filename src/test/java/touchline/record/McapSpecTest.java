package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import touchline.testing.PythonMcap;
import touchline.transport.Envelope;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Files Touchline writes follow the MCAP spec to the letter: the independent Python reader
 * reads them through the summary and indexes, and every chunk index, message index entry,
 * statistic and summary offset agrees with the records it describes; for every compression.
 */
class McapSpecTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @EnumSource(ChunkCompression.class)
    void everyIndexAgreesWithWhatItPointsTo(ChunkCompression compression) throws Exception {
        PythonMcap.require("mcap", "zstandard", "lz4");
        List<Envelope> sent = RecordingFixture.team(3, 20);
        Path file = dir.resolve(compression + ".mcap");
        RecordingFixture.write(file, sent, new EnvelopeWriter.Options(0, 0, 16 * 1024, List.of())
                .withCompression(compression));
        long chunks;
        try (Recording r = Recording.open(file)) {
            chunks = r.mcap().chunkCount();
            assertTrue(chunks > 3, "several chunks: " + chunks);
            assertEquals(sent, RecordingFixture.readAll(r), "Touchline reads its own " + compression + " file");
            assertTrue(r.problems().isEmpty(), r.problems().toString());
        }
        assertEquals(PythonMcap.indexedRead(sent.size(), chunks), PythonMcap.run(PythonMcap.INDEXED_READ, file));
    }

    @Test
    void messagesArrivingOutOfOrderAreIndexedInLogTimeOrder() throws Exception {
        PythonMcap.require("mcap");
        // envelopes of several network threads reach the recorder slightly out of order
        List<Envelope> sent = new ArrayList<>(RecordingFixture.team(2, 5));
        for (int i = 0; i + 1 < sent.size(); i += 2) {
            sent.set(i, sent.set(i + 1, sent.get(i)));
        }
        Path file = dir.resolve("unordered.mcap");
        RecordingFixture.write(file, sent, new EnvelopeWriter.Options(0, 0, 8 * 1024, List.of()));
        long chunks;
        try (McapReader r = McapReader.open(file)) {
            chunks = r.chunkCount();
        }
        assertEquals(PythonMcap.indexedRead(sent.size(), chunks), PythonMcap.run(PythonMcap.INDEXED_READ, file));
    }

    @Test
    void theSampleRecordingFollowsTheSpec() throws Exception {
        PythonMcap.require("mcap");
        Path sample = Path.of("samples/demo-team.mcap");
        long chunks;
        long messages;
        try (McapReader r = McapReader.open(sample)) {
            chunks = r.chunkCount();
            messages = r.messageCount();
        }
        assertEquals(PythonMcap.indexedRead(messages, chunks), PythonMcap.run(PythonMcap.INDEXED_READ, sample));
    }
}
