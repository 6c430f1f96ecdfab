package touchline.cli;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

import java.io.PrintWriter;
import java.io.StringWriter;

import static org.junit.jupiter.api.Assertions.*;

/** {@code touchline serve} headless: it prints the URL to open (with its token) and its statistics, then stops. */
@Tag("integration")
class ServeCommandTest {

    private record Run(int exit, String out, String err) {
    }

    private static Run serve(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new Main());
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        String[] all = new String[args.length + 1];
        all[0] = "serve";
        System.arraycopy(args, 0, all, 1, args.length);
        int exit = cli.execute(all);
        return new Run(exit, out.toString(), err.toString());
    }

    @Test
    void servesOnLoopbackPrintsTheUrlWithItsTokenAndAStatisticsLine() {
        Run run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--token", "s3cret",
                "--seconds", "1", "--stats-every", "1");
        assertEquals(0, run.exit(), run.err());
        assertTrue(run.out().matches("(?s).*ws://127\\.0\\.0\\.1:\\d+/\\?token=s3cret\\n.*"), run.out());
        assertTrue(run.out().contains("viewers 0, subscriptions 0, channels 2"), run.out()); // /gc/state, /touchline/matchMode
    }

    @Test
    void aTokenFileOthersMayReadStopsItBeforeServingAnOwnerOnlyOneIsUsed(@org.junit.jupiter.api.io.TempDir
                                                                          java.nio.file.Path tmp) throws Exception {
        java.nio.file.Path f = tmp.resolve("token");
        java.nio.file.Files.writeString(f, "fromfile\n");
        java.nio.file.Files.setPosixFilePermissions(f, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
        Run run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--token-file", f.toString(),
                "--seconds", "1");
        assertEquals(2, run.exit(), run.err());
        assertTrue(run.err().contains("chmod 600"), run.err());
        assertFalse(run.out().contains("ws://"), run.out());
        java.nio.file.Files.setPosixFilePermissions(f, java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"));
        run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--token-file", f.toString(),
                "--seconds", "1", "--stats-every", "1");
        assertEquals(0, run.exit(), run.err());
        assertTrue(run.out().matches("(?s).*ws://127\\.0\\.0\\.1:\\d+/\\?token=fromfile\\n.*"), run.out());
    }

    @Test
    void withATeamTheBudgetMeterIsAThirdConsoleState() throws Exception {
        int teamPort;
        try (java.net.DatagramSocket free = new java.net.DatagramSocket(0, java.net.InetAddress.getLoopbackAddress())) {
            teamPort = free.getLocalPort();
        }
        Run run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--team", "13",
                "--team-port", Integer.toString(teamPort), "--seconds", "2", "--stats-every", "1");
        assertEquals(0, run.exit(), run.err());
        // /gc/state, /touchline/matchMode and /team/budget
        assertTrue(run.out().contains("viewers 0, subscriptions 0, channels 3"), run.out());
    }

    @Test
    void aBrokenTeamKeyOrContradictoryKeyOptionsStopItBeforeServing(@org.junit.jupiter.api.io.TempDir java.nio.file.Path tmp)
            throws Exception {
        java.nio.file.Path keys = tmp.resolve("keys");
        new touchline.security.KeyDir(keys).create(false, new java.security.SecureRandom(), java.time.Instant.now());
        java.nio.file.Files.writeString(keys.resolve("team.key"), "team-key = 00\nkey-id = 00000000\n");
        Run run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--keys", keys.toString(),
                "--seconds", "1");
        assertEquals(2, run.exit(), run.err());
        assertTrue(run.err().contains("team.key: team-key must be 64 hex digits"), run.err());
        assertFalse(run.out().contains("ws://"), run.out());
        run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--keys", keys.toString(),
                "--insecure", "--seconds", "1");
        assertEquals(2, run.exit(), run.err());
        assertTrue(run.err().contains("--insecure and --keys contradict each other"), run.err());
    }

    @Test
    void aTeamSchemaThatIsNotOneIsReportedAndNothingIsServed() throws Exception {
        java.nio.file.Path bad = java.nio.file.Files.createTempFile("not-a-schema", ".desc");
        java.nio.file.Files.writeString(bad, "hello");
        Run run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--proto", bad.toString(),
                "--seconds", "1");
        assertEquals(2, run.exit());
        assertTrue(run.err().contains("not a protobuf descriptor set"), run.err());
        assertFalse(run.out().contains("ws://"), run.out());
    }

    @Test
    void aRecordingIsServedThroughTheReplayWithoutTakingTheRobotsPort() {
        Run run = serve(samples("demo-team.mcap"), "--port", "0",
                "--speed", "20", "--seconds", "2", "--stats-every", "1");
        assertEquals(0, run.exit(), run.err());
        assertTrue(run.out().contains("serving the recording"), run.out());
        assertFalse(run.out().contains("hearing robots"), run.out());
        // the recording's robots become channels beside the two console states
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("channels (\\d+)").matcher(run.out());
        int most = 0;
        while (m.find()) {
            most = Math.max(most, Integer.parseInt(m.group(1)));
        }
        assertTrue(most > 2, run.out());
    }

    @Test
    void tlsNeedsBothItsCertificateAndItsKey() {
        Run run = serve("--port", "0", "--robots-port", "0", "--robots-bind", "127.0.0.1", "--tls-cert", "cert.pem",
                "--seconds", "1");
        assertEquals(2, run.exit());
        assertTrue(run.err().contains("both --tls-cert and --tls-key"), run.err());
    }

    private static String samples(String name) {
        return java.nio.file.Path.of("samples", name).toAbsolutePath().toString();
    }
}
