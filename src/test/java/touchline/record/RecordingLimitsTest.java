package touchline.record;

import com.google.protobuf.DescriptorProtos.FieldDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.cli.RecoverCommand;
import touchline.cli.ReplayCommand;
import touchline.protocol.MessageKinds;
import touchline.proto.Fumanoid;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A recording costs what it is worth: a small file that claims huge chunks, or whose chunks
 * expand to millions of envelopes, is read up to its {@link ExpansionLimit} and the rest is
 * said; a schema of many files loads in linear time. Costs are counted (bytes allocated,
 * envelopes read, bytes written), never timed; a {@code @Timeout} only guards against the
 * quadratic work that once made such inputs run for minutes.
 */
class RecordingLimitsTest {

    @TempDir
    Path dir;

    private static final byte[] EMPTY_JSON = "{}".getBytes(StandardCharsets.UTF_8);

    private Path file(String name, byte[] bytes) throws Exception {
        Path f = dir.resolve(name);
        Files.write(f, bytes);
        return f;
    }

    /** Bytes this thread allocated so far (the JVM counts them; nothing is timed). */
    private static long allocated() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean()).getCurrentThreadAllocatedBytes();
    }

    private static long envelopes(Recording r) {
        long n = 0;
        Recording.Cursor c = r.cursor(Long.MIN_VALUE);
        while (c.next() != null) {
            n++;
        }
        return n;
    }

    private static boolean noted(Recording r, String words) {
        return r.problems().stream().anyMatch(p -> p.contains(words));
    }

    @Test
    void chunksClaimingAQuarterGigabyteEachAreRefusedBeforeAnythingIsAllocated() throws Exception {
        // the reproducer: a few KB of zstd chunks, each holding one message and claiming 256 MB
        CraftedMcap crafted = CraftedMcap.json();
        for (int i = 0; i < 40; i++) {
            crafted.chunk(ChunkCompression.ZSTD, CraftedMcap.messages(1, EMPTY_JSON, i), i, McapReader.MAX_CHUNK_BYTES);
        }
        Path f = file("claims.mcap", crafted.bytes());
        assertTrue(Files.size(f) < 8 * 1024, Files.size(f) + " bytes");
        long before = allocated();
        try (Recording r = Recording.open(f)) {
            assertEquals(0, envelopes(r));
            long spent = allocated() - before;
            assertTrue(spent < 32L << 20, "reading " + Files.size(f) + " bytes allocated " + (spent >> 20) + " MB");
            assertEquals(40, r.mcap().refusedChunks());
            assertTrue(noted(r, "40 of 40 chunks (from byte "), r.problems().toString());
            assertTrue(noted(r, "--max-expansion"), r.problems().toString());
        }
    }

    @Test
    void aClaimWithinTheLimitIsDecompressedInStepsOfWhatTheFrameHolds() throws Exception {
        // 2 MB of padding allow 64 MB more: five chunks claiming 12 MB each pass, each holding 33 bytes
        CraftedMcap crafted = CraftedMcap.json().padding(2 << 20);
        for (int i = 0; i < 5; i++) {
            crafted.chunk(ChunkCompression.ZSTD, CraftedMcap.messages(1, EMPTY_JSON, i), i, 12L << 20);
        }
        Path f = file("steps.mcap", crafted.bytes());
        long before = allocated();
        try (Recording r = Recording.open(f)) {
            assertEquals(0, envelopes(r));
            long spent = allocated() - before;
            assertTrue(spent < 16L << 20, "five 12 MB claims of 33 bytes each allocated " + (spent >> 20) + " MB");
            assertEquals(0, r.mcap().refusedChunks());
            assertTrue(noted(r, "its zstd frame holds 33 bytes, the chunk says " + (12L << 20)), r.problems().toString());
        }
    }

    /** 24 zstd chunks of 4 MiB, each 127 100 copies of one 33-byte message: about 3 million envelopes in a file of a few KB. */
    private Path expanding() throws Exception {
        CraftedMcap crafted = CraftedMcap.json();
        byte[] records = CraftedMcap.messages(PER_CHUNK, EMPTY_JSON, 0);
        for (int i = 0; i < 24; i++) {
            crafted.chunk(ChunkCompression.ZSTD, records, i * 1_000_000_000L);
        }
        return file("expanding.mcap", crafted.bytes());
    }

    private static final int PER_CHUNK = (4 << 20) / 33;

    @Test
    void aSmallFileExpandingToMillionsOfEnvelopesPlaysUpToTheLimitAndSaysTheRest() throws Exception {
        Path f = expanding();
        long size = Files.size(f);
        assertTrue(size < 64 * 1024, size + " bytes");
        try (Recording r = Recording.open(f)) {
            // 16 MB beyond the file's size: four of the 4 MiB chunks
            assertEquals(4L * PER_CHUNK, envelopes(r));
            assertEquals(20, r.mcap().refusedChunks());
            assertTrue(noted(r, "20 of 24 chunks (from byte "), r.problems().toString());
            assertTrue(noted(r, "may expand to 16 MB (32 times its size more, at least 16 MB, at most 8 GB;"
                    + " --max-expansion raises the ratio)"), r.problems().toString());
        }
        try (Recording r = Recording.open(f, new MessageKinds(), new ExpansionLimit(100_000))) {
            assertEquals(24L * PER_CHUNK, envelopes(r), "a user who trusts the file reads all of it");
            assertEquals(0, r.mcap().refusedChunks());
        }
    }

    @Test
    void replayInfoAndRecoverSayWhatTheLimitRefusedAndRecoverWritesNoMore() throws Exception {
        Path f = expanding();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = new CommandLine(new ReplayCommand()).setOut(new PrintWriter(out)).setErr(new PrintWriter(err))
                .execute(f.toString(), "--info");
        assertEquals(0, code, err.toString());
        assertTrue(out.toString().contains("channel /flood (no schema/json) " + 4L * PER_CHUNK + " messages"), out.toString());
        assertTrue(err.toString().contains("note: 20 of 24 chunks"), err.toString());

        Path copy = dir.resolve("copy.mcap");
        StringWriter recovered = new StringWriter();
        err = new StringWriter();
        code = new CommandLine(new RecoverCommand()).setOut(new PrintWriter(recovered)).setErr(new PrintWriter(err))
                .execute(f.toString(), "--out", copy.toString());
        assertEquals(0, code, err.toString());
        assertTrue(recovered.toString().contains("recovered " + 4L * PER_CHUNK + " messages"), recovered.toString());
        assertTrue(err.toString().contains("note: 20 of 24 chunks"), err.toString());
        // 16 MB of records and their message indexes, not the 100 MB the file expands to
        assertTrue(Files.size(copy) < 32L << 20, Files.size(copy) + " bytes written");

        err = new StringWriter();
        code = new CommandLine(new ReplayCommand()).setOut(new PrintWriter(new StringWriter()))
                .setErr(new PrintWriter(err)).execute(f.toString(), "--info", "--max-expansion", "0");
        assertEquals(2, code);
        assertTrue(err.toString().contains("--max-expansion is at least 1"), err.toString());
    }


    /**
     * A file of the GameController's packets only, {@code chunks} zstd chunks of 4 MiB each
     * holding one recorded packet over and over: about a million packets in a few KB.
     */
    private Path gameControllerFlood(String name, int chunks, long startNanos) throws Exception {
        Path recorded = dir.resolve("recorded.mcap");
        RecordingFixture.write(recorded, RecordingFixture.team(1, 2), EnvelopeWriter.Options.defaults());
        try (Recording r = Recording.open(recorded)) {
            McapReader.Cursor c = r.mcap().cursor(0);
            for (McapReader.McapMessage m = c.next(); m != null; m = c.next()) {
                touchline.transport.Envelope e = r.toEnvelope(m);
                if (e != null && touchline.transport.GameStateReader.isGameState(e)) {
                    McapReader.ChannelInfo gc = r.mcap().channels().get(m.channelId());
                    McapReader.Schema schema = r.mcap().schemas().get(gc.schemaId());
                    CraftedMcap crafted = new CraftedMcap(gc, schema);
                    byte[] records = CraftedMcap.messages((4 << 20) / (31 + m.data().length), m.data(), startNanos);
                    for (int i = 0; i < chunks; i++) {
                        crafted.chunk(ChunkCompression.ZSTD, records, startNanos);
                    }
                    return file(name, crafted.bytes());
                }
            }
        }
        throw new AssertionError("the fixture has no GameController packet");
    }

    @Test
    void twoSmallFilesFullOfGameControllerPacketsReplayInTheWindowsHeap() throws Exception {
        // once: every packet of both files kept for the clock alignment, OutOfMemoryError in 512 MB
        Path a = gameControllerFlood("a.mcap", 40, 1_000_000_000L);
        Path b = gameControllerFlood("b.mcap", 40, 2_000_000_000L);
        assertTrue(Files.size(a) < 64 * 1024, Files.size(a) + " bytes");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String classpath = System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
        Path err = dir.resolve("replay.err");
        Process p = new ProcessBuilder(java, "-Xmx512m", "-cp", classpath, "touchline.cli.Main", "replay",
                a.toString(), b.toString(), "--headless")
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(err.toFile()).start();
        p.getOutputStream().close();
        boolean ended = p.waitFor(180, TimeUnit.SECONDS); // a guard against the old minutes
        if (!ended) {
            p.destroyForcibly();
        }
        String said = Files.readString(err);
        assertTrue(ended, "replay did not end: " + said);
        assertEquals(0, p.exitValue(), said);
        assertTrue(said.contains("note: a.mcap: 36 of 40 chunks") && said.contains("note: b.mcap: 36 of 40 chunks"),
                said);
        assertTrue(said.contains("file b.mcap: +1.000 s,"), said);
        assertTrue(said.contains("replayed ") && said.contains(" from 2 files"), said);
    }

    @Test
    // a guard only: one registry build per file took 21 s for 8 000 files, minutes for these
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aSchemaOfThirtyThousandFilesLoadsWithOneRegistryBuild() throws Exception {
        int files = 30_000;
        FileDescriptorSet.Builder set = FileDescriptorSet.newBuilder();
        for (int i = 0; i < files; i++) {
            set.addFile(FileDescriptorProto.newBuilder().setName("team/f" + i + ".proto").setPackage("team")
                    .addDependency(Fumanoid.getDescriptor().getName())
                    .addExtension(FieldDescriptorProto.newBuilder().setName("k" + i).setNumber(5000 + i)
                            .setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL)
                            .setType(FieldDescriptorProto.Type.TYPE_INT32).setExtendee(".fumanoid.Message")));
        }
        byte[] schema = set.build().toByteArray();
        CraftedMcap crafted = new CraftedMcap(new McapReader.ChannelInfo(1, 1, "/team", "protobuf", Map.of()),
                new McapReader.Schema(1, "fumanoid.Message", "protobuf", schema));
        MessageKinds kinds = new MessageKinds();
        try (Recording r = Recording.open(file("schema.mcap", crafted.bytes()), kinds)) {
            assertEquals(java.util.List.of(), r.problems());
        }
        for (int i = 0; i < files; i += 997) {
            assertEquals("k" + i, kinds.kindOf(5000 + i));
            assertTrue(kinds.registry().findExtensionByNumber(Fumanoid.Message.getDescriptor(), 5000 + i) != null);
        }
    }
}
