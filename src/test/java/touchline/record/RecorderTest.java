package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.transport.EnvelopeBus;
import touchline.transport.Envelope;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class RecorderTest {

    @TempDir
    Path dir;

    @Test
    void recordsWhatTheBusCarriesAndReplaysItEqual() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 30);
        Path file = dir.resolve("bus.mcap");
        EnvelopeBus bus = new EnvelopeBus();
        Recorder recorder = new Recorder(file, EnvelopeWriter.Options.defaults()).start();
        try (AutoCloseable ignored = bus.subscribe(recorder)) {
            sent.forEach(bus::accept);
        }
        recorder.close();
        RecorderStats stats = recorder.stats();
        assertEquals(sent.size(), stats.received());
        assertEquals(sent.size(), stats.written());
        assertEquals(0, stats.dropped());
        assertNull(stats.failure());
        assertEquals(Files.size(file), stats.bytes(), 4096);
        try (Recording r = Recording.open(file)) {
            assertEquals(sent, RecordingFixture.readAll(r));
        }
    }

    @Test
    void aRecorderThatIsNeverClosedHasItsDataOnDiskWithinASecond() throws Exception {
        List<Envelope> sent = RecordingFixture.team(2, 5);
        Path file = dir.resolve("killed.mcap");
        Recorder recorder = new Recorder(file, EnvelopeWriter.Options.defaults()).start();
        sent.forEach(recorder::accept);
        // like kill -9: nobody closes the recorder; the time-based chunk flush must put it on disk
        long deadline = System.nanoTime() + 5_000_000_000L;
        List<Envelope> back = List.of();
        while (System.nanoTime() < deadline && back.size() < sent.size()) {
            Path copy = dir.resolve("copy.mcap");
            Files.copy(file, copy, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            if (Files.size(copy) < 8) {
                continue; // the disk thread has not written the file's magic yet
            }
            try (Recording r = Recording.open(copy)) {
                back = RecordingFixture.readAll(r);
                assertFalse(r.problems().isEmpty(), "no footer yet is reported");
            }
        }
        assertEquals(sent, back);
        recorder.close();
    }

    @Test
    void aDiskThatFallsBehindMakesTheRecorderDropAndCountInsteadOfBlocking() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 20);
        Path file = dir.resolve("drops.mcap");
        // tiny chunks: every envelope hands a chunk to the disk thread, which is held
        EnvelopeWriter.Options options = new EnvelopeWriter.Options(0, 0, 64, List.of());
        Recorder recorder = new Recorder(file, options, 4096).start();
        java.util.concurrent.CountDownLatch release = new java.util.concurrent.CountDownLatch(1);
        recorder.holdDisk(release);
        sent.forEach(recorder::accept); // returns although nothing reaches the disk
        RecorderStats during = recorder.stats();
        assertTrue(during.dropped() > 0, "a disk that is 4 KB behind refuses envelopes");
        assertTrue(during.written() > 0, "until then envelopes were taken");
        release.countDown();
        recorder.close();
        RecorderStats stats = recorder.stats();
        assertEquals(sent.size(), stats.received());
        assertEquals(sent.size(), stats.written() + stats.dropped());
        assertNull(stats.failure());
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertEquals(stats.written(), back.size());
            assertTrue(r.problems().isEmpty(), "a complete file: " + r.problems());
        }
    }

    @Test
    void aFileThatCannotBeCreatedFailsAtOnce() {
        Path missing = dir.resolve("no/such/dir/x.mcap");
        assertThrows(java.io.IOException.class, () -> new Recorder(missing, EnvelopeWriter.Options.defaults()));
    }
}
