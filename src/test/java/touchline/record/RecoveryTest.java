package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.PythonMcap;
import touchline.transport.Envelope;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A recording cut anywhere (a killed recorder, a power cut) becomes, through {@link Recovery},
 * a finished file with every envelope that was readable in the cut one, which the
 * independent Python reader opens through its index.
 */
class RecoveryTest {

    @TempDir
    Path dir;

    @Test
    void aCutRecordingRecoversToAFinishedFileWithEverythingReadable() throws Exception {
        PythonMcap.require("mcap");
        List<Envelope> sent = RecordingFixture.team(3, 20);
        Path whole = dir.resolve("whole.mcap");
        RecordingFixture.write(whole, sent, new EnvelopeWriter.Options(0, 0, 8 * 1024, List.of()));
        byte[] bytes = Files.readAllBytes(whole);
        for (int cut : new int[]{bytes.length / 3, bytes.length * 2 / 3, bytes.length - 10}) {
            Path damaged = dir.resolve("cut" + cut + ".mcap");
            Files.write(damaged, Arrays.copyOf(bytes, cut));
            List<Envelope> readable;
            try (Recording r = Recording.open(damaged)) {
                readable = RecordingFixture.readAll(r);
            }
            Path recovered = dir.resolve("recovered" + cut + ".mcap");
            Recovery.Result result = new Recovery(damaged).writeTo(recovered);
            assertEquals(readable.size(), result.messages());
            assertFalse(result.problems().isEmpty(), "says the file did not finish");
            try (Recording r = Recording.open(recovered)) {
                assertTrue(r.mcap().indexed(), "finished: summary and footer");
                assertTrue(r.problems().isEmpty(), r.problems().toString());
                assertEquals(readable, RecordingFixture.readAll(r));
            }
            long chunks;
            try (McapReader r = McapReader.open(recovered)) {
                chunks = r.chunkCount();
            }
            assertEquals(PythonMcap.indexedRead(readable.size(), chunks), PythonMcap.run(PythonMcap.INDEXED_READ, recovered));
        }
    }
}
