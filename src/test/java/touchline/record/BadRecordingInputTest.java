package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import picocli.CommandLine;
import touchline.cli.ReplayCommand;
import touchline.testing.Await;
import touchline.transport.Envelope;

import java.io.PrintWriter;
import java.io.RandomAccessFile;
import java.io.StringWriter;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Bad input not covered by {@link DamagedRecordingTest} and {@link HostileRecordingTest}: a
 * file a live {@link Recorder} is still writing, a chunk whose declared decompressed length
 * is wrong (uncompressed and zstd), and files cut at each structural point (inside the
 * magic, after it, in the header, in a chunk's header, in its records, at the data end, in
 * the summary, in the footer). Each says what it skipped, plays what is readable, never throws.
 */
class BadRecordingInputTest {

    @TempDir
    Path dir;

    @Test
    void aFileStillBeingWrittenPlaysWhatIsOnDiskAndSaysItIsUnfinished() throws Exception {
        List<Envelope> sent = RecordingFixture.team(2, 6);
        Path file = dir.resolve("live.mcap");
        // small chunks: each is handed to the disk as soon as it is full
        try (Recorder recorder = new Recorder(file, new EnvelopeWriter.Options(0, 0, 2048, List.of())).start()) {
            List<Envelope> first = sent.subList(0, sent.size() / 2);
            first.forEach(recorder::accept);
            Await.until("chunks on disk", () -> readableNow(file) > 0);
            try (Recording r = Recording.open(file)) {
                // the recorder goes on writing while the file is open and read
                sent.subList(sent.size() / 2, sent.size()).forEach(recorder::accept);
                List<Envelope> back = RecordingFixture.readAll(r);
                assertFalse(back.isEmpty());
                assertEquals(sent.subList(0, back.size()), back, "a prefix of what was recorded");
                assertFalse(r.mcap().indexed());
                assertTrue(r.notes().lines().get(0).startsWith("the recording is unfinished: it has no footer (it is"
                        + " still being written"), r.notes().lines().toString());
            }
            String[] replay = replay(file);
            assertTrue(replay[1].contains("note: the recording is unfinished"), replay[1]);
            assertTrue(replay[0].lines().count() > 0, "what is on disk plays");
        }
        try (Recording r = Recording.open(file)) {
            assertEquals(sent, RecordingFixture.readAll(r), "once closed, the file is complete");
            assertTrue(r.notes().lines().isEmpty(), r.notes().lines().toString());
        }
    }

    private static int readableNow(Path file) {
        try {
            if (Files.size(file) < 8) {
                return 0;
            }
            try (Recording r = Recording.open(file)) {
                return RecordingFixture.readAll(r).size();
            }
        } catch (java.io.IOException | RecordingException e) {
            return 0;
        }
    }

    @ParameterizedTest
    @EnumSource(value = ChunkCompression.class, names = {"NONE", "ZSTD"})
    void aChunkWhoseDecompressedLengthIsWrongIsSkippedAndTheRestPlays(ChunkCompression compression) throws Exception {
        List<Envelope> sent = RecordingFixture.team(2, 6);
        Path file = dir.resolve("length-" + compression + ".mcap");
        RecordingFixture.write(file, sent, new EnvelopeWriter.Options(0, 0, 4096, List.of()).withCompression(compression));
        long second;
        try (McapReader r = McapReader.open(file)) {
            second = r.blocksForTest().get(1).offset();
        }
        // opcode, length, start time, end time, then the uncompressed size
        long sizeField = second + 9 + 8 + 8;
        try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw")) {
            raf.seek(sizeField);
            long declared = Long.reverseBytes(raf.readLong());
            raf.seek(sizeField);
            raf.writeLong(Long.reverseBytes(declared + 17));
        }
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertTrue(back.size() < sent.size() && back.size() > sent.size() / 2, back.size() + " of " + sent.size());
            assertEquals(sent.get(sent.size() - 1), back.get(back.size() - 1), "the chunks after it play");
            String said = String.join("\n", r.notes().lines());
            assertTrue(said.contains("chunk at byte " + second + " is "), said);
            assertTrue(compression == ChunkCompression.NONE ? said.contains("is corrupt") && said.contains("bytes)")
                    : said.contains("is damaged: its zstd frame"), said);
            assertTrue(said.contains("its messages are skipped, the rest plays"), said);
        }
    }

    @Test
    void aFileCutAtEachStructuralPointSaysSoAndPlaysWhatIsBeforeTheCut() throws Exception {
        List<Envelope> sent = RecordingFixture.team(2, 4);
        Path whole = dir.resolve("whole.mcap");
        RecordingFixture.write(whole, sent, new EnvelopeWriter.Options(0, 0, 4096, List.of()));
        byte[] bytes = Files.readAllBytes(whole);
        long firstChunk;
        try (McapReader r = McapReader.open(whole)) {
            firstChunk = r.blocksForTest().get(0).offset();
        }
        ByteBuffer footer = ByteBuffer.wrap(bytes, bytes.length - 8 - 20, 20).order(ByteOrder.LITTLE_ENDIAN);
        long summaryStart = footer.getLong();
        long dataEnd = summaryStart - 13; // opcode, length, CRC
        assertEquals(0x0F, bytes[(int) dataEnd]);

        Map<String, Long> cuts = new LinkedHashMap<>();
        cuts.put("after the magic", 8L);
        cuts.put("inside the header record", 14L);
        cuts.put("inside the first chunk's header", firstChunk + 20);
        cuts.put("inside the first chunk's records", firstChunk + 900);
        cuts.put("at the data end", dataEnd);
        cuts.put("inside the summary", summaryStart + 40);
        cuts.put("inside the footer", (long) bytes.length - 20);
        for (Map.Entry<String, Long> cut : cuts.entrySet()) {
            Path part = dir.resolve("cut.mcap");
            Files.write(part, Arrays.copyOf(bytes, cut.getValue().intValue()));
            try (Recording r = Recording.open(part)) {
                List<Envelope> back = RecordingFixture.readAll(r);
                assertEquals(sent.subList(0, back.size()), back, cut.getKey());
                assertTrue(r.notes().lines().stream().anyMatch(l -> l.startsWith("the recording is unfinished")),
                        cut.getKey() + ": " + r.notes().lines());
                if (cut.getValue() >= dataEnd) {
                    assertEquals(sent, back, cut.getKey() + ": every chunk is before the cut");
                }
            }
            String[] replay = replay(part);
            assertTrue(replay[1].contains("note: the recording is unfinished"), cut.getKey() + ": " + replay[1]);
        }
        // cut inside the magic: not recognisable as MCAP at all
        Path five = dir.resolve("five.mcap");
        Files.write(five, Arrays.copyOf(bytes, 5));
        StringWriter err = new StringWriter();
        CommandLine c = new CommandLine(new ReplayCommand());
        c.setOut(new PrintWriter(new StringWriter()));
        c.setErr(new PrintWriter(err));
        assertEquals(1, c.execute(five.toString(), "--headless"));
        assertTrue(err.toString().contains("five.mcap is not an MCAP recording"), err.toString());
    }

    private static String[] replay(Path file) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine c = new CommandLine(new ReplayCommand());
        c.setOut(new PrintWriter(out));
        c.setErr(new PrintWriter(err));
        assertEquals(0, c.execute(file.toString(), "--headless"), err.toString());
        return new String[]{out.toString(), err.toString()};
    }
}
