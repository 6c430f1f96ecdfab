package touchline.cli;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.record.McapReader;
import touchline.record.RecordingException;
import touchline.testing.Await;
import touchline.testing.PythonMcap;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every way a {@code touchline record} ends leaves a file the independent Python reader
 * opens through its summary: Ctrl+C (SIGINT) and SIGTERM sent to a real recorder process,
 * and {@code kill -9} followed by {@code touchline recover}. A loopback "robot" sends status
 * datagrams; the file must hold every one the recorder had written before the end.
 */
@Tag("integration")
class RecordingEndsTest {

    private static final int ROBOT = 7;
    private static final Pattern LISTENING = Pattern.compile("recording UDP port (\\d+) to ");

    /** Counts /robot/7/status messages through the summary and indexes; prints "count statistics-count". */
    private static final String COUNT_THROUGH_INDEX = """
            import sys
            from mcap.reader import make_reader, SeekingReader
            with open(sys.argv[1], 'rb') as f:
                r = make_reader(f, validate_crcs=True)
                assert isinstance(r, SeekingReader)
                s = r.get_summary()
                assert s is not None and s.statistics is not None, 'no summary'
                n = sum(1 for _ in r.iter_messages(topics=['/robot/7/status']))
                total = sum(1 for _ in r.iter_messages())
                print(n, total == s.statistics.message_count)
            """;

    @TempDir
    Path dir;

    private Process recorder;
    private final List<String> output = new CopyOnWriteArrayList<>();

    @AfterEach
    void stopRecorder() {
        if (recorder != null && recorder.isAlive()) {
            recorder.destroyForcibly();
        }
    }

    @Test
    void ctrlCFinishesTheFileAndPrintsTheSummary() throws Exception {
        endBySignal("INT");
    }

    @Test
    void sigtermFinishesTheFileAndPrintsTheSummary() throws Exception {
        endBySignal("TERM");
    }

    private void endBySignal(String signal) throws Exception {
        PythonMcap.require("mcap");
        Path file = dir.resolve("match.mcap");
        int port = startRecorder(file);
        sendStatuses(port, 25);
        awaitRecorded(file, 25);
        long before = System.nanoTime();
        kill(signal);
        assertTrue(recorder.waitFor(20, TimeUnit.SECONDS), "the recorder ends after SIG" + signal);
        double seconds = (System.nanoTime() - before) / 1e9;
        assertTrue(output.stream().anyMatch(l -> l.startsWith("recorded ") && l.contains("the file is finished")),
                "prints its summary (ended in " + seconds + " s): " + output);
        assertEquals("25 True", PythonMcap.run(COUNT_THROUGH_INDEX, file));
    }

    @Test
    void afterKillMinus9RecoverWritesAFinishedFileWithWhatWasWritten() throws Exception {
        PythonMcap.require("mcap");
        Path file = dir.resolve("killed.mcap");
        int port = startRecorder(file);
        sendStatuses(port, 20);
        awaitRecorded(file, 20);
        sendStatuses(port, 10);
        // the recorder writes its open chunk at least every 0.8 s: these are on disk within a second
        awaitRecorded(file, 30);
        kill("KILL");
        assertTrue(recorder.waitFor(20, TimeUnit.SECONDS));
        assertTrue(PythonMcap.fails(COUNT_THROUGH_INDEX, file), "the killed file has no summary");

        Path recovered = dir.resolve("recovered.mcap");
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new RecoverCommand());
        cli.setOut(new PrintWriter(out));
        cli.setErr(new PrintWriter(err));
        assertEquals(0, cli.execute(file.toString(), "--out", recovered.toString()), err.toString());
        assertTrue(out.toString().startsWith("recovered "), out.toString());
        assertTrue(err.toString().contains("did not finish"), "says what was wrong: " + err);
        assertEquals("30 True", PythonMcap.run(COUNT_THROUGH_INDEX, recovered));
    }

    @Test
    void aFullDiskEndsTheRecordingAndSaysHowToRecover() throws Exception {
        Path full = Path.of("/dev/full"); // every write fails with "No space left on device"
        touchline.testing.Requirement.require(Files.isWritable(full), "Linux /dev/full (a full disk to write to)");
        StringWriter out = new StringWriter();
        CommandLine cli = new CommandLine(new RecordCommand());
        cli.setOut(new PrintWriter(out));
        cli.setErr(new PrintWriter(new StringWriter()));
        assertEquals(1, cli.execute("--out", full.toString(), "--port", "0", "--bind", "127.0.0.1", "--seconds", "1"));
        assertTrue(out.toString().contains("No space left on device; the file is not finished: 'touchline recover"),
                out.toString());
    }

    @Test
    void recoverOfSomethingElseSaysWhatIsWrong() throws Exception {
        Path text = dir.resolve("notes.mcap");
        Files.writeString(text, "not a recording");
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new RecoverCommand());
        cli.setErr(new PrintWriter(err));
        assertEquals(1, cli.execute(text.toString()));
        assertTrue(err.toString().contains("not an MCAP recording"), err.toString());
        assertFalse(Files.exists(dir.resolve("notes-recovered.mcap")));
    }

    /** Starts {@code touchline record} in a child JVM with SIGINT handled (a background shell may ignore it). */
    private int startRecorder(Path file) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String classpath = System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
        recorder = new ProcessBuilder("env", "--default-signal=INT,TERM", java, "-cp", classpath, "touchline.cli.Main",
                "record", "--out", file.toString(), "--port", "0", "--bind", "127.0.0.1")
                .redirectErrorStream(true).start();
        recorder.getOutputStream().close();
        Thread reader = new Thread(() -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(recorder.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                    output.add(line);
                }
            } catch (IOException ended) {
                // the process is gone; what it printed is in output
            }
        }, "recorder-output");
        reader.setDaemon(true);
        reader.start();
        Await.until("the recorder listens", () -> output.stream().anyMatch(l -> LISTENING.matcher(l).find())
                || !recorder.isAlive());
        assertTrue(recorder.isAlive(), "the recorder started: " + output);
        assertFalse(ignores(recorder.pid(), 2), "SIGINT is not ignored in the recorder process");
        for (String line : output) {
            Matcher m = LISTENING.matcher(line);
            if (m.find()) {
                return Integer.parseInt(m.group(1));
            }
        }
        throw new AssertionError("no port in " + output);
    }

    /** Whether signal {@code number} is ignored by process {@code pid} (its SigIgn mask in /proc). */
    private static boolean ignores(long pid, int number) throws IOException {
        Path status = Path.of("/proc", Long.toString(pid), "status");
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                long mask = Long.parseUnsignedLong(line.substring(7).trim(), 16);
                return (mask & (1L << (number - 1))) != 0;
            }
        }
        return false;
    }

    private void kill(String signal) throws Exception {
        Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(recorder.pid())).inheritIO().start();
        assertTrue(kill.waitFor(10, TimeUnit.SECONDS) && kill.exitValue() == 0, "kill -" + signal);
    }

    private static void sendStatuses(int port, int n) throws IOException {
        byte[] status = new FrameCodec().encode(Framing.LENGTH_PREFIX, Fumanoid.Message.newBuilder().setRobotID(ROBOT)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray());
        try (DatagramSocket robot = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            for (int i = 0; i < n; i++) {
                robot.send(new DatagramPacket(status, status.length, InetAddress.getLoopbackAddress(), port));
            }
        }
    }

    /** Waits until the file being written already holds {@code n} statuses of the robot (read as a cut file). */
    private static void awaitRecorded(Path file, int n) throws InterruptedException {
        Await.until(n + " statuses in " + file, () -> statuses(file) >= n);
    }

    private static long statuses(Path file) {
        try (McapReader r = McapReader.open(file)) {
            long n = 0;
            McapReader.Cursor c = r.cursor(0);
            for (McapReader.McapMessage m = c.next(); m != null; m = c.next()) {
                McapReader.ChannelInfo channel = r.channels().get(m.channelId());
                if (channel != null && channel.topic().equals("/robot/" + ROBOT + "/status")) {
                    n++;
                }
            }
            return n;
        } catch (RecordingException notYet) {
            return 0; // nothing written yet
        }
    }
}
