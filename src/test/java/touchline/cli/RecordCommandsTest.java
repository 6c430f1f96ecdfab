package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.proto.Fumanoid;
import touchline.record.Recording;
import touchline.record.bench.SyntheticTeam;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
        Run r = run(new RecordCommand(port -> sink -> {
            sent.forEach(sink::accept);
            return () -> { };
        }), "--out", file.toString(), "--seconds", "1");
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
        assertTrue(r.out().contains("Z IN FUMANOID robot=2 status 74 B"), r.out().substring(0, 600));
    }

    @Test
    void replayOfSomethingElseSaysWhatIsWrong() throws Exception {
        Path text = dir.resolve("x.mcap");
        Files.writeString(text, "not a recording");
        Run r = run(new ReplayCommand(), text.toString(), "--headless");
        assertEquals(1, r.exit());
        assertTrue(r.err().contains("is not an MCAP recording"), r.err());
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
    void theStandInUdpSourceClassifiesDatagrams() {
        FrameCodec frames = new FrameCodec();
        MessageCodec codec = new MessageCodec(new MessageKinds());
        InetSocketAddress peer = new InetSocketAddress("127.0.0.1", 4000);
        byte[] status = frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(5)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray());
        Envelope e = RecordCommand.UdpSource.envelope(1, peer, status, frames, codec);
        assertEquals(5, e.robotId());
        assertEquals("status", e.kind());
        Envelope gc = RecordCommand.UdpSource.envelope(1, peer, "RGme....".getBytes(), frames, codec);
        assertEquals(Channel.GAMECONTROLLER, gc.channel());
        Envelope bad = RecordCommand.UdpSource.envelope(1, peer, new byte[]{0x50, 0x51, 0, 9, 1}, frames, codec);
        assertTrue(bad.isMalformed());
        assertEquals(Channel.RELIABLE_STREAM, RecordCommand.UdpSource.envelope(1, peer, new byte[]{3, 1, 7}, frames, codec).channel());
    }
}
