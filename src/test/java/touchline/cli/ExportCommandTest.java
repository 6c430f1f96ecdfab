package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.proto.Fumanoid;
import touchline.record.EnvelopeWriter;
import touchline.record.McapReader;
import touchline.record.foxglove.FoxgloveFixture;
import touchline.transport.Envelope;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code touchline export --format csv --channel} and {@code --format foxglove} on a recording made here. */
class ExportCommandTest {

    private static final long T0 = 1_760_000_000_000_000L;

    @TempDir
    Path dir;

    private record Run(int exit, String out, String err) { }

    private static Run run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new ExportCommand());
        cli.setOut(new PrintWriter(out));
        cli.setErr(new PrintWriter(err));
        int exit = cli.execute(args);
        return new Run(exit, out.toString(), err.toString());
    }

    private Path recording(List<Envelope> sent) throws Exception {
        Path file = dir.resolve("match.mcap");
        try (EnvelopeWriter w = new EnvelopeWriter(file, EnvelopeWriter.Options.defaults())) {
            for (Envelope e : sent) {
                w.write(e);
            }
        }
        return file;
    }

    @Test
    void csvOfAnyChannelHasAColumnPerFieldPathAndARowPerMessage() throws Exception {
        List<Envelope> sent = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            sent.add(FoxgloveFixture.status(T0 + i * 200_000L, 2, 100 * i, -50 * i, 0.25f * i));
            sent.add(FoxgloveFixture.text(T0 + i * 200_000L + 1, 2, "behaviour", "line " + i + ", with comma"));
        }
        Path file = recording(sent);

        Run r = run(file.toString(), "--format", "csv", "--channel", "/robot/2/status");
        assertEquals(0, r.exit(), r.err());
        List<String> lines = r.out().lines().toList();
        List<String> header = Arrays.asList(lines.get(0).split(","));
        assertEquals(List.of("time", "log_time_ns"), header.subList(0, 2));
        assertEquals(6, lines.size(), "a header and one row per status");
        for (int i = 0; i < 5; i++) {
            String[] row = lines.get(i + 1).split(",", -1);
            Fumanoid.Status s = sent.get(2 * i).extension(Fumanoid.status);
            assertEquals(Long.toString(sent.get(2 * i).timeMicros() * 1000), row[1]);
            assertEquals(String.format("%d.%09d", i / 5, i * 200_000_000L % 1_000_000_000L), row[0]);
            assertEquals("2", row[header.indexOf("robotID")]);
            assertEquals(Float.toString(s.getRobotPosition().getX()), row[header.indexOf("status.robotPosition.x")]);
            assertEquals(Float.toString(s.getRobotPosition().getTheta()), row[header.indexOf("status.robotPosition.theta")]);
            assertEquals("80", row[header.indexOf("status.batteryPercent")]);
            assertEquals("striker", row[header.indexOf("status.robotName")]);
        }

        Run text = run(file.toString(), "--format", "csv", "--channel", "/robot/2/debugText");
        assertEquals(0, text.exit(), text.err());
        List<String> rows = text.out().lines().toList();
        assertEquals(6, rows.size());
        for (int i = 0; i < 5; i++) {
            assertTrue(rows.get(i + 1).endsWith(",behaviour,\"line " + i + ", with comma\""), rows.get(i + 1));
        }
    }

    @Test
    void csvOfAStandardChannelInAnExportAndClearErrors() throws Exception {
        Path file = recording(List.of(FoxgloveFixture.text(T0, 4, "o", "hello"), FoxgloveFixture.text(T0 + 5, 4, "o", "again")));
        Path export = dir.resolve("fox.mcap");
        Run fox = run(file.toString(), "--format", "foxglove", "--out", export.toString());
        assertEquals(0, fox.exit(), fox.err());
        assertTrue(fox.err().contains("/robot/4/log: 2"), fox.err());

        Run log = run(export.toString(), "--format", "csv", "--channel", "/robot/4/log");
        assertEquals(0, log.exit(), log.err());
        List<String> lines = log.out().lines().toList();
        List<String> header = Arrays.asList(lines.get(0).split(","));
        assertEquals(List.of("hello", "again"), lines.stream().skip(1)
                .map(l -> l.split(",", -1)[header.indexOf("message")]).toList());
        assertEquals("INFO", lines.get(1).split(",", -1)[header.indexOf("level")]);

        Run missing = run(file.toString(), "--format", "csv", "--channel", "/robot/9/status");
        assertEquals(1, missing.exit());
        assertTrue(missing.err().contains("no channel /robot/9/status") && missing.err().contains("/robot/4/debugText"),
                missing.err());
        assertEquals(2, run(file.toString(), "--format", "foxglove").exit()); // no --out
        assertEquals(2, run(file.toString(), "--format", "xml", "--channel", "/x").exit());
        assertEquals(2, run(file.toString(), "--format", "csv").exit()); // nothing chosen
    }

    @Test
    void theFoxgloveExportKeepsEveryRecordedChannelAndAddsTheStandardOnes() throws Exception {
        Path file = recording(List.of(FoxgloveFixture.text(T0, 1, "o", "x"), FoxgloveFixture.status(T0 + 1, 1, 0, 0, 0)));
        Path export = dir.resolve("out.mcap");
        assertEquals(0, run(file.toString(), "--format", "foxglove", "--out", export.toString()).exit());
        Set<String> before;
        try (McapReader in = McapReader.open(file)) {
            before = in.channels().values().stream().map(McapReader.ChannelInfo::topic).collect(Collectors.toSet());
        }
        try (McapReader out = McapReader.open(export)) {
            Set<String> after = out.channels().values().stream().map(McapReader.ChannelInfo::topic).collect(Collectors.toSet());
            for (String topic : before) {
                assertTrue(after.contains("/touchline" + topic), after.toString()); // the recorded channels, moved aside
            }
            assertTrue(after.containsAll(before), after.toString()); // ... and their content under the same names
            assertTrue(after.containsAll(Set.of("/robot/1/log", "/tf", "/field/scene")), after.toString());
            assertFalse(before.contains("/tf"));
            assertEquals(2 + 2 + 3, out.messageCount()); // recorded, their content, log + transform + scene
        }
        try (touchline.record.Recording back = touchline.record.Recording.open(export)) {
            assertEquals(2, back.mcap().channels().values().stream()
                    .filter(c -> !c.metadata().containsKey(touchline.record.Recording.STANDARD_CHANNEL)).count());
        }
    }
}
