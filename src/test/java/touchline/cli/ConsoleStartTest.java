package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The console's start fails clearly: no display, a robot side not built each end the command
 * with one sentence saying what to do and an exit code, never a stack trace (a port in use:
 * {@link PortInUseTest}).
 */
class ConsoleStartTest {

    @TempDir
    Path dir;

    private static void assertOneSentence(String err, String... words) {
        List<String> lines = err.lines().filter(l -> l.startsWith("touchline ")).toList();
        assertEquals(1, lines.size(), err);
        for (String w : words) {
            assertTrue(lines.get(0).contains(w), w + " in: " + err);
        }
        assertFalse(err.contains("Exception") || err.contains("\tat "), "no stack trace: " + err);
    }

    @Test
    void aFrameCapOutOfRangeIsNamedBeforeAnythingStarts() throws Exception {
        StringWriter err = new StringWriter();
        int code = Main.execute(new String[] {"console", "--bind", "127.0.0.1", "--port", "0", "--max-fps", "0",
                "--layouts", dir.toString()}, new PrintWriter(err, true));
        assertEquals(StartFailure.BAD_INPUT, code);
        assertOneSentence(err.toString(), "--max-fps must be between 1 and 60", "not 0");
    }

    /** A fresh JVM, so the test's own display settings (headless Monocle) are not inherited. */
    private Run run(Map<String, String> env, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path")));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().remove("DISPLAY");
        pb.environment().remove("WAYLAND_DISPLAY");
        pb.environment().putAll(env);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), out);
        return new Run(p.exitValue(), out);
    }

    private record Run(int code, String output) { }

    @Test
    void noDisplayIsNamedWithWhatToDo() throws Exception {
        Run r = run(Map.of(), "touchline.cli.Main", "console", "--bind", "127.0.0.1", "--port", "0",
                "--layouts", dir.toString());
        assertEquals(StartFailure.NO_DISPLAY, r.code(), r.output());
        assertOneSentence(r.output(), "needs a display", "DISPLAY", "touchline listen");
    }

    @Test
    void aMissingRobotSideBuildIsNamedWithWhatToDo() throws Exception {
        Path missing = dir.resolve("not-built");
        Run r = run(Map.of(), "-Dtouchline.robotside.bin=" + missing, "touchline.cli.Main", "screenshots",
                "--out", dir.resolve("shots").toString());
        assertEquals(StartFailure.ROBOT_SIDE_MISSING, r.code(), r.output());
        assertOneSentence(r.output(), "not built", missing.resolve("touchline-robot").toString(), "./touchline build");
    }

    @Test
    void aDisplayIsFoundOnX11OrWaylandAndNotAskedForOnHeadlessMonocle() {
        assertNull(ConsoleCommand.missingDisplay(Map.of("DISPLAY", ":0"), "", "Linux"));
        assertNull(ConsoleCommand.missingDisplay(Map.of("WAYLAND_DISPLAY", "wayland-0"), "", "Linux"));
        assertNull(ConsoleCommand.missingDisplay(Map.of(), "Monocle", "Linux"));
        assertNull(ConsoleCommand.missingDisplay(Map.of(), "", "Windows 11"));
        assertTrue(ConsoleCommand.missingDisplay(Map.of("DISPLAY", " "), "", "Linux").contains("DISPLAY"));
    }
}
