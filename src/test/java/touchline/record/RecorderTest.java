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
import static org.junit.jupiter.api.Assertions.assertTrue;

class RecorderTest {

    @TempDir
    Path dir;

    @Test
    void recordsWhatTheBusCarriesAndReplaysItEqual() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 30);
        Path file = dir.resolve("bus.mcap");
        EnvelopeBus bus = new EnvelopeBus();
        Recorder recorder = new Recorder(file, EnvelopeWriter.Options.defaults());
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
        Recorder recorder = new Recorder(file, EnvelopeWriter.Options.defaults());
        sent.forEach(recorder::accept);
        // like kill -9: nobody closes the recorder; the time-based chunk flush must put it on disk
        long deadline = System.nanoTime() + 5_000_000_000L;
        List<Envelope> back = List.of();
        while (System.nanoTime() < deadline && back.size() < sent.size()) {
            Path copy = dir.resolve("copy.mcap");
            Files.copy(file, copy, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            try (Recording r = Recording.open(copy)) {
                back = RecordingFixture.readAll(r);
                assertFalse(r.problems().isEmpty(), "no footer yet is reported");
            }
        }
        assertEquals(sent, back);
        recorder.close();
    }

    @Test
    void aFullQueueDropsAndCountsInsteadOfBlocking() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 20);
        Path file = dir.resolve("drops.mcap");
        Recorder recorder = new Recorder(file, EnvelopeWriter.Options.defaults(), 4);
        sent.forEach(recorder::accept);
        recorder.close();
        RecorderStats stats = recorder.stats();
        assertEquals(sent.size(), stats.received());
        assertEquals(sent.size(), stats.written() + stats.dropped());
        assertTrue(stats.dropped() > 0, "a four-slot queue cannot keep up with a burst");
        try (Recording r = Recording.open(file)) {
            assertEquals(stats.written(), RecordingFixture.readAll(r).size());
        }
    }
}
