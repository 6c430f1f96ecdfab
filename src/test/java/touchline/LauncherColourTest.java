package touchline;

import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The scripts' coloured words ({@code packaging/colour.sh}, used by {@code ./touchline},
 * {@code packaging/package.sh} and {@code check-fresh.sh}): plain text into a pipe or a file,
 * colours on a terminal (a pseudo-terminal made by {@code script}), none with NO_COLOR.
 */
class LauncherColourTest {

    private static final String ESC = "\u001b";

    private static String run(List<String> command, String noColor) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        if (noColor != null) {
            pb.environment().put("NO_COLOR", noColor);
        } else {
            pb.environment().remove("NO_COLOR");
        }
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), out);
        return out;
    }

    @Test
    void doctorIntoAPipeHasNoEscapeCodes() throws Exception {
        String out = run(List.of("./touchline", "doctor"), null);
        assertTrue(out.contains("Touchline doctor") && out.contains("Java"), out);
        assertFalse(out.contains(ESC), "escape codes in piped output:\n" + out);
    }

    @Test
    void theScriptsLinesAreColouredOnATerminalOnly() throws Exception {
        String lines = ". packaging/colour.sh; paint out 32 ok; echo; paint err '1;31' fix >&2; echo >&2";
        String piped = run(List.of("bash", "-c", lines), null);
        assertTrue(piped.contains("ok") && piped.contains("fix") && !piped.contains(ESC), piped);
        String terminal = run(List.of("script", "-qec", "bash -c \"" + lines + "\"", "/dev/null"), null);
        assertTrue(terminal.contains(ESC + "[32mok" + ESC + "[0m") && terminal.contains(ESC + "[1;31mfix"), terminal);
        String asked = run(List.of("script", "-qec", "bash -c \"" + lines + "\"", "/dev/null"), "1");
        assertTrue(asked.contains("ok") && !asked.contains(ESC), asked);
    }
}
