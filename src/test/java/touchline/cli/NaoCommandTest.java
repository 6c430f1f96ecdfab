package touchline.cli;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import touchline.testing.RobotProcess;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.ConnectionState;
import touchline.transport.nao.FakeNaoCamera;
import touchline.transport.nao.FakeNaoRobot;
import touchline.transport.nao.NaoLink;
import touchline.transport.nao.NaoLinkConfig;

import java.io.InputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

class NaoCommandTest {

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        CommandLine cli = new CommandLine(new NaoCommand());
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        return cli.execute(args);
    }

    /**
     * The fakes are JeroMQ servers without CURVE: an old robot side. Off the field: calls do not
     * listen for a GameController (another test's on port 3838 would hold them back).
     */
    private int runInsecure(String... args) {
        java.util.List<String> withFlags = new java.util.ArrayList<>(java.util.List.of(args));
        withFlags.add("--insecure");
        if (!args[0].equals("cam")) {
            withFlags.addAll(java.util.List.of("--gc-port", "0"));
        }
        return run(withFlags.toArray(String[]::new));
    }

    @Test
    void callPrintsTheOutcomeAndSetsTheExitCode() throws Exception {
        try (FakeNaoRobot robot = new FakeNaoRobot(0)) {
            String target = "127.0.0.1:" + robot.port();
            assertEquals(0, runInsecure("call", target, "Test.echo", "[HeadYaw, 0.5, 3]"));
            assertEquals("[\"HeadYaw\", 0.5f, 3]", out.toString().strip());
            assertEquals(1, runInsecure("call", target, "Test.fail"));
            assertTrue(err.toString().contains("failed on purpose"), err.toString());
            assertEquals(0, runInsecure("methods", target, "Test"));
            assertTrue(out.toString().contains("Test: echo void fail sleep"), out.toString());
            assertEquals(2, run("call", target, "noDot"));
        }
    }

    /** A GameController on loopback: {@code packet} to {@code port} every {@code periodMs}. */
    private static void sendEvery(ScheduledExecutorService field, DatagramSocket gc, byte[] packet, int port, long periodMs) {
        field.scheduleAtFixedRate(() -> {
            try {
                gc.send(new DatagramPacket(packet, packet.length, InetAddress.getLoopbackAddress(), port));
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }, 0, periodMs, TimeUnit.MILLISECONDS);
    }

    /**
     * The wait before the first call is shown on the terminal: a line when it starts, one when it
     * ends and why — at once when the GameController (on loopback, INITIAL every 500 ms) is heard,
     * after the whole listen when none is.
     */
    @Test
    void theFirstListenIsALineWhenItStartsAndOneWhenItEnds() throws Exception {
        byte[] initial;
        try (InputStream in = getClass().getResourceAsStream("/golden/gamecontroller/hsl20/00-initial.bin")) {
            initial = in.readAllBytes();
        }
        int gcPort = freePort();
        try (FakeNaoRobot robot = new FakeNaoRobot(0)) {
            String target = "127.0.0.1:" + robot.port();
            assertEquals(0, run("call", target, "Test.echo", "1", "--insecure", "--gc-port", Integer.toString(gcPort)));
            assertTrue(err.toString().contains("touchline nao: match mode: listening for a GameController before "
                    + "talking to robots ("), err.toString());
            assertTrue(err.toString().contains("touchline nao: match mode: no GameController heard in "
                    + touchline.app.game.MatchMode.LISTEN_FIRST_MS + " ms: talking to robots"), err.toString());

            err.getBuffer().setLength(0);
            ScheduledExecutorService gameController = Executors.newSingleThreadScheduledExecutor();
            try (DatagramSocket gc = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
                sendEvery(gameController, gc, initial, gcPort, 500);
                assertEquals(0, run("call", target, "Test.echo", "2", "--insecure", "--gc-port",
                        Integer.toString(gcPort)));
                assertTrue(err.toString().contains("touchline nao: match mode: heard INITIAL (GameController at "
                        + "127.0.0.1:" + gc.getLocalPort() + "): talking to robots"), err.toString());
            } finally {
                gameController.shutdownNow();
            }
        }
    }

    @Test
    void anAbsentRobotIsAClearMessage() throws Exception {
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
            port = s.getLocalPort();
        }
        assertEquals(1, runInsecure("call", "127.0.0.1:" + port, "--connect-timeout", "300", "ALMotion.ping"));
        assertTrue(err.toString().contains("no NAO RPC module answering"), err.toString());
        assertTrue(err.toString().contains("a NAO that runs with CURVE keys does not answer an insecure console"),
                err.toString());
    }

    @Test
    void camSavesAJpeg() throws Exception {
        Path file = Files.createTempFile("frame", ".jpg");
        try (FakeNaoCamera camera = new FakeNaoCamera()) {
            assertEquals(0, runInsecure("cam", "127.0.0.1:" + camera.port(), "--save", file.toString(), "--resolution", "1"));
        }
        byte[] jpeg = Files.readAllBytes(file);
        assertEquals((byte) 0xFF, jpeg[0]);
        assertEquals((byte) 0xD8, jpeg[1]);
        assertTrue(out.toString().contains("320x240"), out.toString());
        assertEquals(2, run("cam", "127.0.0.1:1", "--save", file.toString(), "--resolution", "7"));
    }

    @Test
    void withoutKeysOrInsecureItSaysWhereTheKeysShouldBe(@org.junit.jupiter.api.io.TempDir Path keys)
            throws Exception {
        try (FakeNaoRobot robot = new FakeNaoRobot(0)) {
            assertEquals(1, run("call", "127.0.0.1:" + robot.port(), "Test.echo", "1", "--keys", keys.toString()));
            assertTrue(err.toString().contains(keys.resolve("console.secret") + ": missing"), err.toString());
            assertTrue(err.toString().contains("touchline keys new"), err.toString());
            assertTrue(err.toString().contains("--insecure"), err.toString());
            assertEquals(1, run("cam", "127.0.0.1:1", "--save", keys.resolve("f.jpg").toString(), "--keys",
                    keys.toString()));
        }
    }

    private static int freePort() throws Exception {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            return probe.getLocalPort();
        }
    }

    /**
     * On a field: while a GameController on loopback sends PLAYING (the official v20 datagram,
     * every 100 ms) to the command's GameController port, the call is held back (exit code 3,
     * the reason on stderr) and the {@code touchline-nao-sim} never runs it; with the
     * GameController gone the same command goes through.
     */
    @Tag("integration")
    @Test
    void aCallDuringPlayIsHeldBackAndNeverReachesTheRobot() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-nao-sim");
        byte[] playing;
        try (InputStream in = getClass().getResourceAsStream("/golden/gamecontroller/hsl20/07-playing-after-delay.bin")) {
            playing = in.readAllBytes();
        }
        int gcPort = freePort();
        try (RobotProcess sim = RobotProcess.of(List.of(RobotProcess.binDir().resolve("touchline-nao-sim").toString(),
                "--bind", "127.0.0.1", "--rpc-port", "0", "--cam-port", "0")).start();
             NaoLink check = new NaoLink("127.0.0.1", sim.port(), NaoLinkConfig.defaults(), e -> { }, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            String target = "127.0.0.1:" + sim.port();
            ScheduledExecutorService gameController = Executors.newSingleThreadScheduledExecutor();
            try (DatagramSocket gc = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
                sendEvery(gameController, gc, playing, gcPort, 100);
                assertEquals(NaoCommand.HELD_BACK, run("call", target, "ALMemory.insertData", "Touchline/cli", "7",
                        "--insecure", "--gc-port", Integer.toString(gcPort), "--listen", "10000"), "out: " + out + " err: " + err);
                assertTrue(err.toString().contains("held back: match mode, game is PLAYING"), err.toString());
            } finally {
                gameController.shutdownNow();
            }
            touchline.testing.Await.until("a checking link online", () -> check.state() == ConnectionState.ONLINE);
            assertInstanceOf(CallOutcome.Failed.class, check.call("ALMemory", "getData", "Touchline/cli").get(30, TimeUnit.SECONDS),
                    "the held call never ran on the robot");

            // the GameController is gone: a console starting now hears no play
            assertEquals(0, run("call", target, "ALMemory.insertData", "Touchline/cli", "7", "--insecure",
                    "--gc-port", Integer.toString(gcPort)), err.toString());
            CallOutcome stored = check.call("ALMemory", "getData", "Touchline/cli").get(30, TimeUnit.SECONDS);
            assertTrue(stored.ok(), stored.describe());
            assertEquals("7", stored.describe(), "the call ran once play was over");
        }
    }
}
