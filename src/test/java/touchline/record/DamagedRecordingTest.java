package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.transport.Envelope;

import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Bad input: cut files, corrupt chunks, other files, unparsable schemas, newer formats. */
class DamagedRecordingTest {

    @TempDir
    Path dir;

    private Path recorded(List<Envelope> sent) throws Exception {
        Path file = dir.resolve("whole.mcap");
        RecordingFixture.write(file, sent, new EnvelopeWriter.Options(0, 0, 8 * 1024, List.of()));
        return file;
    }

    @Test
    void aFileCutAtRandomOffsetsReplaysUpToTheCutWithAClearMessage() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 20);
        byte[] whole = Files.readAllBytes(recorded(sent));
        Random random = new Random(7);
        for (int i = 0; i < 12; i++) {
            int cut = 9 + random.nextInt(whole.length - 40);
            Path part = dir.resolve("cut" + i + ".mcap");
            Files.write(part, Arrays.copyOf(whole, cut));
            try (Recording r = Recording.open(part)) {
                List<Envelope> back = RecordingFixture.readAll(r);
                assertEquals(sent.subList(0, back.size()), back, "a prefix of what was recorded, cut at " + cut);
                assertFalse(r.problems().isEmpty(), "the cut is reported");
                assertTrue(r.problems().get(0).contains("did not finish") || r.problems().get(0).contains("cut"),
                        r.problems().toString());
                assertFalse(r.mcap().indexed());
            }
        }
        // a cut just before the footer leaves every chunk intact
        Path nearlyWhole = dir.resolve("nearly.mcap");
        Files.write(nearlyWhole, Arrays.copyOf(whole, whole.length - 10));
        try (Recording r = Recording.open(nearlyWhole)) {
            assertEquals(sent, RecordingFixture.readAll(r));
        }
    }

    @Test
    void aCorruptChunkIsReportedAndTheRestPlays() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 20);
        Path file = recorded(sent);
        long chunkOffset;
        try (McapReader r = McapReader.open(file)) {
            assertTrue(r.chunkCount() > 3);
        }
        byte[] bytes = Files.readAllBytes(file);
        // the second chunk: find the second CHUNK opcode boundary through the reader's own index
        try (McapReader r = McapReader.open(file)) {
            chunkOffset = secondChunkOffset(r);
        }
        try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw")) {
            raf.seek(chunkOffset + 200);
            raf.write(bytes[(int) chunkOffset + 200] ^ 0x55);
        }
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertTrue(back.size() < sent.size() && back.size() > sent.size() / 2, back.size() + " of " + sent.size());
            assertEquals(sent.get(sent.size() - 1), back.get(back.size() - 1), "the chunks after it play");
            assertTrue(r.problems().stream().anyMatch(p -> p.contains("corrupt") && p.contains("CRC")), r.problems().toString());
        }
    }

    private static long secondChunkOffset(McapReader r) {
        return r.blocksForTest().get(1).offset();
    }

    @Test
    void aFileThatIsNotMcapGivesAClearError() throws Exception {
        Path text = dir.resolve("notes.mcap");
        Files.writeString(text, "hello, this is not a recording");
        RecordingException e = assertThrows(RecordingException.class, () -> Recording.open(text));
        assertTrue(e.getMessage().contains("is not an MCAP recording"), e.getMessage());
        Path empty = dir.resolve("empty.mcap");
        Files.write(empty, new byte[0]);
        RecordingException none = assertThrows(RecordingException.class, () -> Recording.open(empty));
        assertTrue(none.getMessage().contains("empty.mcap is empty"), none.getMessage());
        RecordingException missing = assertThrows(RecordingException.class, () -> Recording.open(dir.resolve("nope.mcap")));
        assertTrue(missing.getMessage().startsWith("cannot open"), missing.getMessage());
    }

    @Test
    void aSchemaThatDoesNotParseIsReportedAndTheBytesStillPlay() throws Exception {
        List<Envelope> sent = RecordingFixture.team(1, 3);
        Path file = dir.resolve("badschema.mcap");
        try (McapWriter w = new McapWriter(file, 4096)) {
            EnvelopeLayout layout = new EnvelopeLayout();
            int schema = w.addSchema("fumanoid.Message", "protobuf", "not a descriptor set".getBytes(StandardCharsets.UTF_8));
            Envelope status = sent.stream().filter(e -> e.kind().equals("status")).findFirst().orElseThrow();
            EnvelopeLayout.Key key = layout.keyOf(status);
            int channel = w.addChannel(schema, key.topic(), key.encoding(), key.metadata());
            int header = key.framing().headerSize();
            w.addMessage(channel, status.timeMicros() * 1000, status.timeMicros() * 1000, status.raw(), header,
                    status.raw().length - header);
        }
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertEquals(1, back.size());
            assertEquals(sent.stream().filter(e -> e.kind().equals("status")).findFirst().orElseThrow(), back.get(0));
            assertTrue(r.problems().stream().anyMatch(p -> p.contains("does not parse")), r.problems().toString());
        }
    }

    @Test
    void aRecordingFromANewerVersionSaysSoAndPlays() throws Exception {
        Path file = dir.resolve("newer.mcap");
        List<Envelope> sent = RecordingFixture.team(1, 2);
        try (EnvelopeWriter w = new EnvelopeWriter(file, EnvelopeWriter.Options.defaults())) {
            for (Envelope e : sent) {
                w.write(e);
            }
            w.metadataForTest(McapWriter.FORMAT_METADATA, java.util.Map.of("version", "9"));
        }
        try (Recording r = Recording.open(file)) {
            assertEquals(sent, RecordingFixture.readAll(r));
            assertTrue(r.problems().stream().anyMatch(p -> p.contains("newer Touchline")), r.problems().toString());
        }
    }
}
