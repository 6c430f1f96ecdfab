package touchline.cli;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A port taken by another program ends {@code listen}, {@code console} (also as the demo starts
 * it), and {@code serve} with one sentence naming the port, what it is for and the flag that moves
 * it, exit code 3, never a stack trace.
 */
@Tag("integration")
class PortInUseTest {

    @TempDir
    Path dir;

    private record Run(int exit, String err) {
    }

    private static Run run(String... args) {
        StringWriter err = new StringWriter();
        int exit = Main.execute(args, new PrintWriter(err, true));
        return new Run(exit, err.toString());
    }

    private static void assertNamed(Run run, String command, String... words) {
        assertEquals(StartFailure.PORT_IN_USE, run.exit(), run.err());
        List<String> lines = run.err().lines().filter(l -> l.startsWith("touchline " + command + ": ")).toList();
        assertEquals(1, lines.size(), run.err());
        for (String w : words) {
            assertTrue(lines.get(0).contains(w), w + " in: " + run.err());
        }
        assertFalse(run.err().contains("Exception") || run.err().contains("\tat "), "no stack trace: " + run.err());
    }

    private static DatagramSocket takenUdp() throws Exception {
        return new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
    }

    @Test
    void listenNamesTheRobotsPortAndItsFlag() throws Exception {
        try (DatagramSocket taken = takenUdp()) {
            int port = taken.getLocalPort();
            assertNamed(run("listen", "--bind", "127.0.0.1", "--port", Integer.toString(port), "--seconds", "1"),
                    "listen", "UDP port " + port + " (robots) on 127.0.0.1 is already in use", "start with --port N",
                    "--port " + (port + 1));
        }
    }

    @Test
    void theConsoleAndTheDemosConsoleNameTheRobotsPortAndItsFlag() throws Exception {
        try (DatagramSocket taken = takenUdp()) {
            int port = taken.getLocalPort();
            List<String> console = List.of("console", "--bind", "127.0.0.1", "--port", Integer.toString(port),
                    "--layouts", dir.toString());
            assertNamed(run(console.toArray(String[]::new)), "console",
                    "UDP port " + port + " (robots) on 127.0.0.1 is already in use", "start with --port N");
            List<String> demo = new ArrayList<>(console); // ./touchline demo: console --demo --team 13
            demo.addAll(List.of("--demo", "--team", "13"));
            assertNamed(run(demo.toArray(String[]::new)), "console",
                    "UDP port " + port + " (robots) on 127.0.0.1 is already in use", "start with --port N");
        }
    }

    @Test
    void serveNamesTheWebSocketPortAndTheRobotsPortEachWithItsFlag() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            int port = taken.getLocalPort();
            assertNamed(run("serve", "--port", Integer.toString(port), "--robots-port", "0", "--robots-bind",
                    "127.0.0.1", "--seconds", "1"), "serve",
                    "WebSocket port " + port + " (viewers) on 127.0.0.1 is already in use", "start with --port N");
        }
        try (DatagramSocket taken = takenUdp()) {
            int port = taken.getLocalPort();
            assertNamed(run("serve", "--port", "0", "--robots-port", Integer.toString(port), "--robots-bind",
                    "127.0.0.1", "--seconds", "1"), "serve",
                    "UDP port " + port + " (robots) on 127.0.0.1 is already in use", "start with --robots-port N");
        }
    }
}
