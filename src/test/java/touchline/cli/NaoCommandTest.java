package touchline.cli;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import touchline.transport.nao.FakeNaoCamera;
import touchline.transport.nao.FakeNaoRobot;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
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

    /** The fakes are JeroMQ servers without CURVE: an old robot side. */
    private int runInsecure(String... args) {
        String[] withFlag = java.util.Arrays.copyOf(args, args.length + 1);
        withFlag[args.length] = "--insecure";
        return run(withFlag);
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
}
