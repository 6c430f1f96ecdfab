package touchline.record;

import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import picocli.CommandLine;
import touchline.cli.ReplayCommand;
import touchline.transport.Envelope;

import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.RandomAccessFile;
import java.io.StringWriter;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Recordings are input from outside (teams swap logs): each file here once made the reader
 * allocate gigabytes, throw, overflow its stack, play a chunk a thousand times or look up a
 * host name. Now each says what it skipped, plays what is readable, and nothing escapes.
 */
class HostileRecordingTest {

    @TempDir
    Path dir;

    private List<Envelope> sent;

    private byte[] wellFormed(EnvelopeWriter.Options options) throws Exception {
        sent = RecordingFixture.team(2, 4);
        Path file = dir.resolve("good.mcap");
        RecordingFixture.write(file, sent, options);
        return Files.readAllBytes(file);
    }

    private byte[] wellFormed() throws Exception {
        return wellFormed(new EnvelopeWriter.Options(0, 0, 4 * 1024, List.of()));
    }

    private Path file(String name, byte[] bytes) throws Exception {
        Path f = dir.resolve(name);
        Files.write(f, bytes);
        return f;
    }

    private static boolean noted(Recording r, String words) {
        return r.problems().stream().anyMatch(p -> p.contains(words));
    }

    @Test
    void aMetadataIndexWhoseLengthOverflowsAllocatesNothing() throws Exception {
        // offset + length wraps around to a negative number: a bounds check written as a sum passes it
        byte[] bytes = McapSurgery.concat(McapRecords.MAGIC,
                McapSurgery.record(McapRecords.METADATA_INDEX, McapSurgery.le(0x1_0000_0000L, 0x7FFF_FFFF_7FFF_FFF0L, 0)),
                McapSurgery.footer(8));
        assertEquals(74, bytes.length);
        try (Recording r = Recording.open(file("74.mcap", bytes))) {
            assertEquals(List.of(), RecordingFixture.readAll(r));
            assertTrue(noted(r, "metadata index entry points outside the file"), r.problems().toString());
        }
    }

    @Test
    void aChunkWithRecordsLengthMinusOneIsSkippedAndTheRestPlays() throws Exception {
        byte[] good = wellFormed();
        byte[] chunk = McapSurgery.record(McapRecords.CHUNK, McapSurgery.le(0L, 0L, 10L, 0, 0, -1L, new byte[10]));
        byte[] bytes = McapSurgery.concat(Arrays.copyOf(good, McapSurgery.dataEnd(good)), chunk);
        try (Recording r = Recording.open(file("minus-one.mcap", bytes))) {
            assertEquals(sent, RecordingFixture.readAll(r));
            assertTrue(noted(r, "impossible sizes"), r.problems().toString());
        }
    }

    @Test
    void recordLengthsNearTwoToTheSixtyThreeAreReportedNotThrown() throws Exception {
        byte[] good = wellFormed();
        byte[] data = Arrays.copyOf(good, McapSurgery.dataEnd(good));
        byte[] huge = McapSurgery.le((byte) McapRecords.MESSAGE, 0x7FFF_FFFF_FFFF_FFF0L, new byte[12]);
        // inside a chunk
        byte[] chunk = McapSurgery.record(McapRecords.CHUNK, McapSurgery.le(0L, 0L, (long) huge.length, 0, 0,
                (long) huge.length, huge));
        try (Recording r = Recording.open(file("inside.mcap", McapSurgery.concat(data, chunk)))) {
            assertEquals(sent, RecordingFixture.readAll(r));
            assertTrue(noted(r, "runs past the chunk's end"), r.problems().toString());
        }
        // in the data section itself: the scan stops there, everything before plays
        try (Recording r = Recording.open(file("outside.mcap", McapSurgery.concat(data, huge)))) {
            assertEquals(sent, RecordingFixture.readAll(r));
            assertTrue(noted(r, "cut off"), r.problems().toString());
        }
    }

    @Test
    void aSummaryListingOneChunkAThousandTimesPlaysItOnce() throws Exception {
        byte[] good = wellFormed();
        int summary = McapSurgery.summaryStart(good);
        int offsets = (int) McapSurgery.u64(good, good.length - 8 - 20 - 9 + 9 + 8);
        List<byte[]> parts = new ArrayList<>(List.of(Arrays.copyOf(good, summary)));
        byte[] firstChunkIndex = null;
        for (McapSurgery.Rec rec : McapSurgery.records(good, summary, offsets)) {
            parts.add(rec.bytes());
            if (rec.opcode() == McapRecords.CHUNK_INDEX && firstChunkIndex == null) {
                firstChunkIndex = rec.bytes();
            }
        }
        for (int i = 1; i < 1000; i++) {
            parts.add(firstChunkIndex);
        }
        parts.add(McapSurgery.footer(summary));
        try (Recording r = Recording.open(file("repeated.mcap", McapSurgery.concat(parts.toArray(byte[][]::new))))) {
            assertTrue(r.mcap().indexed());
            assertEquals(sent, RecordingFixture.readAll(r));
            assertTrue(noted(r, "more than once"), r.problems().toString());
        }
    }

    @ParameterizedTest
    @EnumSource(value = ChunkCompression.class, names = {"ZSTD", "LZ4"})
    void aGarbageCompressedFrameSkipsThatChunkOnly(ChunkCompression compression) throws Exception {
        Path file = file("garbage.mcap", wellFormed(new EnvelopeWriter.Options(0, 0, 4 * 1024, List.of())
                .withCompression(compression)));
        long second;
        try (McapReader r = McapReader.open(file)) {
            second = r.blocksForTest().get(1).offset();
        }
        // the records start after opcode, length, times, size, CRC, the compression's name and the records length
        long records = second + 9 + 8 + 8 + 8 + 4 + 4 + compression.mcapName().length() + 8;
        try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw")) {
            raf.seek(records);
            byte[] garbage = new byte[24];
            Arrays.fill(garbage, (byte) 0xA5);
            raf.write(garbage);
        }
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertTrue(back.size() < sent.size() && back.size() > sent.size() / 2, back.size() + " of " + sent.size());
            assertEquals(sent.get(sent.size() - 1), back.get(back.size() - 1), "the chunks after it play");
            assertTrue(noted(r, "is damaged: its " + compression.mcapName() + " frame"), r.problems().toString());
        }
    }

    @Test
    void channelsWithoutTouchlineMetadataAreSkippedAndReplaySaysSo() throws Exception {
        Path file = dir.resolve("foreign.mcap");
        try (OutputStream out = Files.newOutputStream(file); McapWriter w = new McapWriter(out, 4096)) {
            int good = w.addChannel(0, "/gc/hl12", EnvelopeLayout.RAW_ENCODING, Map.of("touchline.direction", "IN",
                    "touchline.channel", "GAMECONTROLLER", "touchline.robot", "-1", "touchline.kind", "hl12"));
            int noKind = w.addChannel(0, "/robot/1/status", EnvelopeLayout.RAW_ENCODING, Map.of("touchline.direction",
                    "IN", "touchline.channel", "FUMANOID", "touchline.robot", "1"));
            int noFraming = w.addChannel(0, "/robot/2/status", "protobuf", Map.of("touchline.direction", "IN",
                    "touchline.channel", "FUMANOID", "touchline.robot", "2", "touchline.kind", "status",
                    "touchline.layout", "payload"));
            for (int i = 0; i < 3; i++) {
                long t = (1_000_000L + i) * 1_000_000L;
                w.addMessage(good, t, t, new byte[]{1, 2, 3});
                w.addMessage(noKind, t, t, new byte[]{4});
                w.addMessage(noFraming, t, t, new byte[]{5});
            }
        }
        try (Recording r = Recording.open(file)) {
            assertEquals(3, RecordingFixture.readAll(r).size());
            String skipped = r.notes().skippedLine().orElseThrow();
            assertTrue(skipped.startsWith("skipped 6 messages of 2 channels: /robot/1/status (no schema/"
                    + "application/octet-stream: not a complete Touchline channel: no touchline.kind in its metadata) 3,"
                    + " /robot/2/status"), skipped);
            assertTrue(skipped.contains("without touchline.framing) 3"), skipped);
        }
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine replay = new CommandLine(new ReplayCommand());
        replay.setOut(new PrintWriter(out));
        replay.setErr(new PrintWriter(err));
        assertEquals(0, replay.execute(file.toString(), "--headless"));
        assertEquals(3, out.toString().lines().count(), out.toString());
        // raised while playing, after the file was opened: still printed
        assertTrue(err.toString().contains("note: skipped 6 messages of 2 channels: /robot/1/status"), err.toString());
    }

    @Test
    void aSchemaChainOfTwentyThousandImportsIsRefusedWithoutOverflowingTheStack() throws Exception {
        FileDescriptorSet.Builder chain = FileDescriptorSet.newBuilder();
        int n = 20_000;
        for (int i = 0; i < n; i++) {
            FileDescriptorProto.Builder f = FileDescriptorProto.newBuilder().setName("f" + i + ".proto");
            if (i + 1 < n) {
                f.addDependency("f" + (i + 1) + ".proto");
            }
            chain.addFile(f);
        }
        Path file = dir.resolve("deep.mcap");
        try (OutputStream out = Files.newOutputStream(file); McapWriter w = new McapWriter(out, 4096)) {
            w.addSchema("deep.Message", "protobuf", chain.build().toByteArray());
        }
        try (Recording r = Recording.open(file)) {
            assertTrue(noted(r, "levels of imports"), r.problems().toString());
        }
    }

    @Test
    void aHostNameInARecordedPeerIsNeverLookedUp() {
        InetSocketAddress named = EnvelopeLayout.parsePeer("robots.example.invalid:3838");
        assertTrue(named.isUnresolved(), "kept as a name, not resolved");
        assertEquals("robots.example.invalid", named.getHostString());
        InetSocketAddress literal = EnvelopeLayout.parsePeer("10.0.13.7:3838");
        assertFalse(literal.isUnresolved());
        assertEquals("10.0.13.7", literal.getAddress().getHostAddress());
        assertFalse(EnvelopeLayout.isAddressLiteral("10.0.13"), "a short form getByName would treat as a name");
        assertTrue(EnvelopeLayout.isAddressLiteral("fe80:0:0:0:0:0:0:1"));
    }

    @Test
    void anEnvelopeWhosePeerIsANameIsPrintedAndAFailingConsumerIsSaid() throws Exception {
        Path file = dir.resolve("named.mcap");
        try (OutputStream out = Files.newOutputStream(file); McapWriter w = new McapWriter(out, 4096)) {
            int nao = w.addChannel(0, "/nao/out/rpc", EnvelopeLayout.RAW_ENCODING, Map.of("touchline.direction", "OUT",
                    "touchline.channel", "NAO_RPC", "touchline.robot", "4", "touchline.kind", "rpc",
                    "touchline.peer", "nao4.example.invalid:9559"));
            w.addMessage(nao, 1_000_000_000_000L, 1_000_000_000_000L, new byte[]{1, 2});
        }
        StringWriter out = new StringWriter();
        CommandLine replay = new CommandLine(new ReplayCommand());
        replay.setOut(new PrintWriter(out));
        replay.setErr(new PrintWriter(new StringWriter()));
        assertEquals(0, replay.execute(file.toString(), "--headless"));
        assertTrue(out.toString().contains("nao4.example.invalid:9559"), "the line is printed: " + out);

        try (Recording r = Recording.open(file)) {
            new Player(r, e -> {
                throw new IllegalStateException("a view that cannot show it");
            }, new touchline.app.SystemClock()).runToEnd();
            assertTrue(noted(r, "showing a replayed envelope failed"), r.problems().toString());
        }
    }
}
