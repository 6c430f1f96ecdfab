package touchline.cli;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameState8;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.HslPenalty;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code touchline gc} driven through stdin, sending to a socket on 127.0.0.1. */
class GcCommandTest {

    private static String run(String stdin, String... args) {
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(buf, true, StandardCharsets.UTF_8);
        int code = new CommandLine(new GcCommand(new ByteArrayInputStream(stdin.getBytes(StandardCharsets.UTF_8)),
                out)).execute(args);
        assertEquals(0, code, buf.toString(StandardCharsets.UTF_8));
        return buf.toString(StandardCharsets.UTF_8);
    }

    /** The last datagram received before the socket stays quiet for 300 ms. */
    private static byte[] lastDatagram(DatagramSocket socket) throws Exception {
        socket.setSoTimeout(300);
        byte[] last = null;
        byte[] buf = new byte[2048];
        while (true) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                socket.receive(p);
                last = Arrays.copyOf(buf, p.getLength());
            } catch (SocketTimeoutException e) {
                return last;
            }
        }
    }

    @Test
    void aBadDestinationIsSaidBeforeAnythingStarts() {
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(buf, true, StandardCharsets.UTF_8);
        int code = new CommandLine(new GcCommand(new ByteArrayInputStream(new byte[0]), out))
                .execute("--format", "hl12", "--team-a", "13", "--team-b", "7", "--dest", "127.0.0.1:38x8");
        assertEquals(2, code);
        assertEquals("error: --dest bad port in '127.0.0.1:38x8': give a number from 1 to 65535",
                buf.toString(StandardCharsets.UTF_8).strip());
    }

    @Test
    void refereesAGameFromStdin() throws Exception {
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            String dest = "127.0.0.1:" + robot.getLocalPort();
            String out = run("ready\nset\nplay\ngoal 13\npenalty 7 2 physical_contact\nfly away\nplay\nundo\nstatus\n",
                    "--format", "hl12", "--team-a", "13", "--team-b", "7", "--dest", dest, "--return-port", "0", "--rival-port", "-1",
                    "--bind", "127.0.0.1");
            assertTrue(out.contains("ok: goal 13"), out);
            assertTrue(out.contains("state: READY 1st half, kick-off 7, 13 1:0 7"), out);
            assertTrue(out.contains("error: unknown command 'fly'"), out);
            assertTrue(out.contains("refused: illegal now: play"), out);
            assertTrue(out.contains("undid penalty 7 2 physical_contact"), out);
            assertTrue(out.contains("status: READY"), out);
            Decoded<GameControlData> last = new HlGameState12().decode(lastDatagram(robot));
            assertTrue(last.isOk(), last.toString());
            assertEquals(1, last.value().team(13).score());
            assertEquals(GameControlData.STATE_READY, last.value().state());
            assertEquals(0, last.value().team(7).player(2).penalty(), "undo reached the wire");
        }
    }

    @Test
    void refereesAnHslGameByDefault() throws Exception {
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            String out = run("kickoff 5\nset\nplay\ngoal 5\ncorner 14\nset\nplay\npenalize 14 3 pushing\n"
                            + "unpenalize 14 3\ncaution 5 2\ncaution 5 2\ncorner 14\nteammessage 5 600\nstatus\n",
                    "--team-a", "5", "--team-b", "14", "--dest", "127.0.0.1:" + robot.getLocalPort(),
                    "--return-port", "0", "--rival-port", "-1", "--monitor-port", "0", "--bind", "127.0.0.1");
            assertTrue(out.contains("monitors register on /127.0.0.1:"), out);
            assertTrue(out.contains("GameController hsl20 sending"), out);
            assertTrue(out.contains("ok: kick off 5"), out);
            assertTrue(out.contains("robots still see SET"), out);
            assertTrue(out.contains("ok: goal 5"), out);
            assertTrue(out.contains("refused: illegal now: corner kick 14 (READY"), out);
            assertTrue(out.contains("ok: penalize 5 2 cautioned"), out);
            assertTrue(out.contains("ok: corner kick 14"), out);
            assertTrue(out.contains("status: PLAYING STOPPED corner kick 1st half"), out);
            byte[] last = lastDatagram(robot);
            assertEquals(HslGameState20.SIZE, last.length);
            Decoded<GameControlData> d = new HslGameState20().decode(last);
            assertTrue(d.isOk(), d.toString());
            assertEquals(GameControlData.STATE_PLAYING, d.value().state());
            assertTrue(d.value().stopped(), "a corner kick stops play");
            assertEquals(0, d.value().team(5).score(), "a 600-byte team message is illegal communication");
            assertEquals(HslPenalty.SENT_OFF.neutral(), d.value().team(5).player(2).penalty(), "second caution");
            assertEquals(HslPenalty.PUSHING.neutral(), d.value().team(14).player(3).penalty());
            assertEquals(5, d.value().playersPerTeam(), "middle_advanced by default");
            assertEquals(1, d.value().competitionType());
        }
    }

    @Test
    void hslOptionsThatDoNotFitAreErrors() {
        for (String[] args : new String[][]{{"--competition", "tiny"}, {"--players", "4"},
                {"--colour-b", "red"}, {"--colour-a", "pink"}}) {
            ByteArrayOutputStream buf = new ByteArrayOutputStream();
            String[] all = new String[args.length + 4];
            System.arraycopy(new String[]{"--team-a", "5", "--team-b", "14"}, 0, all, 0, 4);
            System.arraycopy(args, 0, all, 4, args.length);
            int code = new CommandLine(new GcCommand(new ByteArrayInputStream(new byte[0]),
                    new PrintStream(buf, true, StandardCharsets.UTF_8))).execute(all);
            assertEquals(2, code, String.join(" ", args));
            assertTrue(buf.toString(StandardCharsets.UTF_8).startsWith("error: "), buf.toString(StandardCharsets.UTF_8));
        }
    }

    @Test
    void sendsTheChosenFormat() throws Exception {
        try (DatagramSocket robot = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            run("ready\n", "--format", "v8", "--team-a", "13", "--team-b", "7", "--dest",
                    "127.0.0.1:" + robot.getLocalPort(), "--return-port", "0", "--rival-port", "-1", "--bind",
                    "127.0.0.1");
            byte[] last = lastDatagram(robot);
            assertEquals(GameState8.SIZE, last.length);
            assertEquals(GameControlData.STATE_READY, new GameState8().decode(last).value().state());
        }
    }

    @Test
    void unknownFormatIsAnError() {
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        int code = new CommandLine(new GcCommand(new ByteArrayInputStream(new byte[0]),
                new PrintStream(buf, true, StandardCharsets.UTF_8)))
                .execute("--format", "hl99", "--team-a", "1", "--team-b", "2");
        assertEquals(2, code);
        assertTrue(buf.toString(StandardCharsets.UTF_8).contains("unknown format"));
    }
}
