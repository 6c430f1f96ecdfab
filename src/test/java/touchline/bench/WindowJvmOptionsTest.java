package touchline.bench;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * The window's JVM options are written three times — the launcher ({@code ./touchline}: JVM_OPTS and
 * UI_HEAP), {@code bench ui --laptop} ({@link LaptopLoadBench#WINDOW_JVM}) and {@code .ci/side-by-side} —
 * because each runs the window its own way; the benchmarks measure what users run only while the three agree.
 */
class WindowJvmOptionsTest {

    @Test
    void theLaunchersWindowOptionsAreTheBenchmarksAndTheSideBySideScripts() throws IOException {
        String launcher = Files.readString(Path.of("touchline"));
        String launcherWindow = group(launcher, "(?m)^JVM_OPTS=\\(([^)]*)\\)") + " " + group(launcher, "(?m)^UI_HEAP=\\(([^)]*)\\)");
        assertEquals(launcherWindow, LaptopLoadBench.WINDOW_JVM, "bench ui --laptop");
        assertEquals(launcherWindow, group(Files.readString(Path.of(".ci/side-by-side")), "(?m)^WINDOW_JVM=\"([^\"]*)\""),
                ".ci/side-by-side");
    }

    /** What the three add on JDK 25 and later (compact object headers) agrees too, and only there. */
    @Test
    void theOptionsAddedOnJdk25AreTheSameInAllThree() throws IOException {
        String launcher = Files.readString(Path.of("touchline"));
        String launcher25 = group(launcher, "(?m)^if \\[ \"\\$\\(java_major\\)\" -ge 25 \\]; then\\s*\\n\\s*JVM_OPTS\\+=\\(([^)]*)\\)");
        assertEquals(launcher25, String.join(" ", LaptopLoadBench.LEANER_JDK25), "bench ui --laptop");
        assertEquals(launcher25, group(Files.readString(Path.of(".ci/side-by-side")), "(?m)^JDK25_JVM=\"([^\"]*)\""),
                ".ci/side-by-side");
    }

    private static String group(String text, String regex) {
        Matcher m = Pattern.compile(regex).matcher(text);
        if (!m.find()) {
            throw new AssertionError("not found: " + regex);
        }
        return m.group(1).trim();
    }
}
