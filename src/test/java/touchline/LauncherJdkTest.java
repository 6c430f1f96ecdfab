package touchline;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The launcher's choice of JDK ({@code ./touchline}: {@code newest_jdk}, {@code java_major}): the
 * newest full JDK from 17 to 25, read from each JDK's {@code release} file. The functions are taken
 * from the launcher itself and run by bash on a directory of made-up JDKs.
 */
class LauncherJdkTest {

    @TempDir
    Path dir;

    private static String function(String name) throws IOException {
        List<String> lines = Files.readAllLines(Path.of("touchline"));
        int start = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith(name + "() {")) {
                start = i;
            } else if (start >= 0 && lines.get(i).equals("}")) {
                return String.join("\n", lines.subList(start, i + 1)) + "\n";
            }
        }
        throw new AssertionError("no function " + name + " in ./touchline");
    }

    private Path jdk(String name, String version, boolean compiler) throws IOException {
        Path home = dir.resolve("jvm").resolve(name);
        Files.createDirectories(home.resolve("bin"));
        Files.writeString(home.resolve("release"), "IMPLEMENTOR=\"test\"\nJAVA_VERSION=\"" + version + "\"\n");
        for (String tool : compiler ? List.of("java", "javac") : List.of("java")) {
            Path t = Files.writeString(home.resolve("bin").resolve(tool), "#!/bin/sh\n");
            Files.setPosixFilePermissions(t, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
        return home;
    }

    private String bash(String script, String path) throws Exception {
        ProcessBuilder pb = new ProcessBuilder("bash", "-c", script).redirectErrorStream(true);
        if (path != null) {
            pb.environment().put("PATH", path + ":/usr/bin:/bin");
        }
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertTrue(p.waitFor(30, TimeUnit.SECONDS), out);
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    @Test
    void theNewestFullJdkFrom17To25IsChosen() throws Exception {
        jdk("java-17-openjdk-amd64", "17.0.15", true);
        Path newest = jdk("temurin-25-jdk-amd64", "25.0.3", true);
        jdk("java-21-openjdk-amd64", "21.0.8", true);
        jdk("jdk-26-ea", "26", true); // not yet tried with this code
        jdk("jre-25-runtime-only", "25.0.3", false); // no compiler: cannot build
        jdk("java-11-openjdk-amd64", "11.0.2", true);
        assertEquals(newest.toString(), bash(function("newest_jdk") + "newest_jdk " + dir.resolve("jvm"), null));
    }

    @Test
    void onlyJdk17OrNoJdkAtAll() throws Exception {
        Path only = jdk("java-17-openjdk-amd64", "17.0.15", true);
        assertEquals(only.toString(), bash(function("newest_jdk") + "newest_jdk " + dir.resolve("jvm"), null));
        assertEquals("", bash(function("newest_jdk") + "newest_jdk " + dir.resolve("nothing-here"), null));
    }

    @Test
    void theFeatureVersionComesFromTheJavaOnThePath() throws Exception {
        Path home = jdk("temurin-25-jdk-amd64", "25.0.3", true);
        Path link = Files.createDirectories(dir.resolve("bin-link"));
        Files.createSymbolicLink(link.resolve("java"), home.resolve("bin/java")); // as update-alternatives does
        assertEquals("25", bash(function("java_major") + "java_major", link.toString()));
        Path broken = jdk("broken", "unknown", true);
        assertEquals("0", bash(function("java_major") + "java_major", broken.resolve("bin").toString()));
    }
}
