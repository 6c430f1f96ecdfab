package touchline;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.DyingConsole;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Issue 36 item 1: when the console's JVM dies the terminal says so, with its crash log, and the
 * demo says what it stopped ({@code packaging/console-end.sh}, sourced by {@code ./touchline}:
 * {@code run_console}, {@code stop_team}). Run by bash with a real JVM that crashes or exits, and
 * real processes for the team.
 */
class LauncherCrashTest {

    @TempDir
    Path dir;

    /** The demo's path: a team of two started, the console run, the team stopped on the way out. */
    private String demo(String consoleArgument) throws Exception {
        String java = ProcessHandle.current().info().command().orElse("java");
        String classes = Path.of(DyingConsole.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        String script = "set -euo pipefail\n"
                + "say() { printf '[touchline] %s\\n' \"$*\" >&2; }\n"
                + ". packaging/console-end.sh\n"
                + "PIDS=() PID_NAMES=()\n"
                + "trap stop_team EXIT\n"
                + "sleep 300 & PIDS+=($!) PID_NAMES+=(\"robot 1\")\n"
                + "sleep 300 & PIDS+=($!) PID_NAMES+=(\"the NAO simulator\")\n"
                + "echo \"team: ${PIDS[*]}\" >&2\n"
                + "run_console '" + java + "' -XX:-CreateCoredumpOnCrash \"$(crash_log_option)\" -cp '" + classes + "' "
                + DyingConsole.class.getName() + " " + consoleArgument + "\n";
        ProcessBuilder pb = new ProcessBuilder("bash", "-c", script).redirectErrorStream(true);
        pb.environment().put("TOUCHLINE_CRASH_DIR", dir.resolve("crashes").toString());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), out);
        assertTrue(p.exitValue() != 0, "the launcher passes the console's failure on: " + out);
        String team = out.lines().filter(l -> l.startsWith("team: ")).findFirst().orElseThrow().substring(6);
        for (String pid : team.split(" ")) {
            assertTrue(ProcessHandle.of(Long.parseLong(pid)).map(h -> !h.isAlive()).orElse(true), "team process " + pid + " stopped");
        }
        assertTrue(out.contains("[touchline] stopped the simulated team: robot 1, the NAO simulator"), out);
        return out;
    }

    @Test
    void aCrashedConsoleIsNamedWithItsCrashLogAndTheDemoSaysWhatItStopped() throws Exception {
        String out = demo("crash");
        String said = out.lines().filter(l -> l.startsWith("[touchline] the console crashed")).findFirst().orElse("");
        assertTrue(said.matches("\\[touchline] the console crashed \\(process \\d+, exit code \\d+\\); its crash log: .*hs_err_pid\\d+\\.log"),
                out);
        Path log = Path.of(said.substring(said.indexOf("its crash log: ") + "its crash log: ".length()));
        assertEquals(dir.resolve("crashes"), log.getParent());
        assertTrue(Files.readString(log).contains("SIGSEGV"), "the JVM's own crash log");
    }

    @Test
    void aConsoleThatEndsWithAnErrorIsNamedWithItsExitCode() throws Exception {
        String out = demo("3");
        assertTrue(out.contains("[touchline] the console ended with exit code 3"), out);
    }
}
