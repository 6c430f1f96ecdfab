package touchline.cli;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.proto.Fumanoid;
import touchline.record.EnvelopeWriter;
import touchline.record.Recording;
import touchline.bench.record.SyntheticTeam;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

@Tag("slow")
class RecordCommandsTest {

    @TempDir
    Path dir;

    private record Run(int exit, String out, String err) { }

    private static Run run(Object command, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(command);
        cli.setOut(new PrintWriter(out));
        cli.setErr(new PrintWriter(err));
        int exit = cli.execute(args);
        return new Run(exit, out.toString(), err.toString());
    }

    private Path recorded(long seconds) throws Exception {
        List<Envelope> sent = new ArrayList<>();
        new SyntheticTeam(3, 1_000_000_000_000L, 1).generate(seconds, sent::add);
        Path file = dir.resolve("cli.mcap");
        // a console without the model (nothing asks the synthetic robots for options) and no GameController port
        Run r = run(new RecordCommand(config -> new touchline.app.Console(config.withGameControllerPort(0),
                new touchline.app.SystemClock(), false), field -> sent.forEach(field.bus()::accept)),
                "--out", file.toString(), "--seconds", "1", "--port", "0", "--bind", "127.0.0.1");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().contains("recorded " + sent.size() + " envelopes (0 dropped)"), r.out());
        return file;
    }

    @Test
    void recordThenReplayHeadlessPrintsOneLinePerEnvelope() throws Exception {
        Path file = recorded(12);
        Run r = run(new ReplayCommand(), file.toString(), "--headless", "--events");
        assertEquals(0, r.exit(), r.err());
        List<String> lines = r.out().lines().toList();
        long envelopes = lines.stream().filter(l -> !l.startsWith("event")).count();
        try (Recording rec = Recording.open(file)) {
            assertEquals(rec.mcap().messageCount(), envelopes);
        }
        assertTrue(lines.contains("event +10.0 s STATE_CHANGE GC: INITIAL → READY"), r.out().substring(0, 300));
        assertTrue(r.out().contains("IN  fumanoid robot 2 10.0.13.12:3858 status"), r.out().substring(0, 600));
    }

    @Test
    void replayOfSomethingElseSaysWhatIsWrong() throws Exception {
        Path text = dir.resolve("x.mcap");
        Files.writeString(text, "not a recording");
        Run r = run(new ReplayCommand(), text.toString(), "--headless");
        assertEquals(1, r.exit());
        assertTrue(r.err().contains("is not an MCAP recording"), r.err());
    }

    /** The laptop's recording and robot 2's own log (its traffic and the GC it heard) on a clock {@code ahead} µs ahead. */
    private Path[] laptopAndRobot(long ahead) throws Exception {
        List<Envelope> team = new ArrayList<>();
        new SyntheticTeam(3, 1_000_000_000_000L, 1).generate(30, team::add);
        Path laptop = dir.resolve("laptop.mcap");
        Path robot = dir.resolve("robot2.mcap");
        try (EnvelopeWriter w = new EnvelopeWriter(laptop, EnvelopeWriter.Options.defaults())) {
            for (Envelope e : team) {
                w.write(e);
            }
        }
        try (EnvelopeWriter w = new EnvelopeWriter(robot, EnvelopeWriter.Options.defaults())) {
            for (Envelope e : team) {
                if (e.robotId() == 2 || e.channel() == Channel.GAMECONTROLLER) {
                    w.write(new Envelope(e.timeMicros() + ahead, e.direction(), e.channel(), e.peer(), e.robotId(),
                            e.kind(), e.message(), e.raw(), e.error()));
                }
            }
        }
        return new Path[]{laptop, robot};
    }

    @Test
    void replayOfSeveralFilesSaysEachFilesOffsetAndPlaysOneMergedOrder() throws Exception {
        Path[] f = laptopAndRobot(2_500_000);
        Run r = run(new ReplayCommand(), f[0].toString(), f[1].toString(), "--headless");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.err().contains("file laptop.mcap: reference clock"), r.err());
        assertTrue(r.err().contains("file robot2.mcap: +2.500 s, 60 GC packets matched, agree within 1 ms"), r.err());
        List<String> lines = r.out().lines().toList();
        assertTrue(lines.stream().anyMatch(l -> l.contains("robot 2") && l.endsWith(" file=robot2.mcap")), lines.get(0));
        assertTrue(lines.stream().noneMatch(l -> l.contains("robot 1") && l.endsWith(" file=robot2.mcap")));
        List<String> times = lines.stream().map(l -> l.substring(0, l.indexOf(' '))).toList();
        assertEquals(times.stream().sorted().toList(), times, "one order of time over both files");
        assertTrue(r.err().contains("from 2 files"), r.err());

        Run given = run(new ReplayCommand(), f[0].toString(), f[1].toString(), "--headless", "--offset",
                "robot2.mcap=+2.0");
        assertEquals(0, given.exit(), given.err());
        assertTrue(given.err().contains("file robot2.mcap: +2.000 s (given)"), given.err());

        Run wrong = run(new ReplayCommand(), f[0].toString(), f[1].toString(), "--offset", "other.mcap=1");
        assertEquals(2, wrong.exit());
        assertTrue(wrong.err().contains("other.mcap is not one of the files"), wrong.err());
    }

    @Test
    void exportWritesPlotsAndTablesAsCsv() throws Exception {
        Path file = recorded(4);
        Path csv = dir.resolve("plot.csv");
        Run r = run(new ExportCommand(), file.toString(), "--robot", "3", "--kind", "debugPlot", "--csv", "--out", csv.toString());
        assertEquals(0, r.exit(), r.err());
        List<String> lines = Files.readAllLines(csv);
        assertEquals("time,vx,vy", lines.get(0));
        assertEquals(41, lines.size(), "10 plot messages a second for 4 s, plus the header");
        assertTrue(lines.get(1).matches("0\\.\\d{6},-?\\d.*,-?\\d.*"), lines.get(1));

        Run table = run(new ExportCommand(), file.toString(), "--robot", "1", "--kind", "table", "--csv");
        assertEquals(0, table.exit(), table.err());
        List<String> rows = table.out().lines().toList();
        assertEquals("time,option,servo,temp", rows.get(0));
        assertEquals(5, rows.size(), "two tables of two rows");
        assertTrue(rows.get(1).contains(",servos,hip,"), rows.get(1));

        Run bad = run(new ExportCommand(), file.toString(), "--robot", "1", "--kind", "status", "--csv");
        assertEquals(2, bad.exit());
        assertTrue(bad.err().contains("not 'status'"), bad.err());
    }

    @Test
    @org.junit.jupiter.api.Tag("integration")
    void recordsLiveUdpTrafficThroughTheConsole() throws Exception {
        java.util.concurrent.atomic.AtomicInteger port = new java.util.concurrent.atomic.AtomicInteger();
        Path file = dir.resolve("live.mcap");
        RecordCommand command = new RecordCommand(touchline.app.Console::new, field -> port.set(field.port()));
        Thread recording = new Thread(() -> run(command, "--out", file.toString(), "--port", "0", "--bind", "127.0.0.1",
                "--seconds", "2"));
        recording.start();
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (port.get() == 0 && System.nanoTime() < deadline) {
            Thread.onSpinWait();
        }
        byte[] status = new FrameCodec().encode(Framing.LENGTH_PREFIX, Fumanoid.Message.newBuilder().setRobotID(7)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray());
        try (java.net.DatagramSocket robot = new java.net.DatagramSocket(0, java.net.InetAddress.getLoopbackAddress())) {
            for (int i = 0; i < 5; i++) {
                robot.send(new java.net.DatagramPacket(status, status.length, java.net.InetAddress.getLoopbackAddress(), port.get()));
            }
        }
        recording.join(20_000);
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = new ArrayList<>();
            Recording.Cursor c = r.cursor(Long.MIN_VALUE);
            for (Envelope e = c.next(); e != null; e = c.next()) {
                back.add(e);
            }
            assertEquals(5, back.stream().filter(e -> e.robotId() == 7 && e.kind().equals("status")
                    && e.channel() == Channel.FUMANOID).count(), back.toString());
            assertTrue(r.problems().isEmpty(), r.problems().toString());
        }
    }
}
