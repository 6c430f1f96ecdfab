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
 * The launcher's choice of JDK ({@code packaging/jdk.sh}, sourced by {@code ./touchline} and
 * {@code packaging/package.sh}: {@code newest_jdk}, {@code java_major}): the newest full JDK from 17
 * to 25, read from each JDK's {@code release} file; the package's JDK 17. Run by bash on a directory
 * of made-up JDKs.
 */
class LauncherJdkTest {

    @TempDir
    Path dir;

    /** The launcher's and the package script's own functions. */
    private static final String FUNCTIONS = ". packaging/jdk.sh\n";

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
        assertEquals(newest.toString(), bash(FUNCTIONS + "newest_jdk 17 25 " + dir.resolve("jvm"), null));
    }

    @Test
    void thePackageTakesJdk17AmongNewerOnes() throws Exception {
        Path seventeen = jdk("java-17-openjdk-amd64", "17.0.15", true);
        jdk("temurin-25-jdk-amd64", "25.0.3", true);
        assertEquals(seventeen.toString(), bash(FUNCTIONS + "newest_jdk 17 17 " + dir.resolve("jvm"), null));
    }

    @Test
    void aJavaNamedDirectlyHasItsVersionToo() throws Exception {
        Path home = jdk("temurin-25-jdk-amd64", "25.0.3", true);
        assertEquals("25", bash(FUNCTIONS + "java_major " + home.resolve("bin/java"), null));
    }

    @Test
    void onlyJdk17OrNoJdkAtAll() throws Exception {
        Path only = jdk("java-17-openjdk-amd64", "17.0.15", true);
        assertEquals(only.toString(), bash(FUNCTIONS + "newest_jdk 17 25 " + dir.resolve("jvm"), null));
        assertEquals("", bash(FUNCTIONS + "newest_jdk 17 25 " + dir.resolve("nothing-here"), null));
    }

    @Test
    void theFeatureVersionComesFromTheJavaOnThePath() throws Exception {
        Path home = jdk("temurin-25-jdk-amd64", "25.0.3", true);
        Path link = Files.createDirectories(dir.resolve("bin-link"));
        Files.createSymbolicLink(link.resolve("java"), home.resolve("bin/java")); // as update-alternatives does
        assertEquals("25", bash(FUNCTIONS + "java_major", link.toString()));
        Path broken = jdk("broken", "unknown", true);
        assertEquals("0", bash(FUNCTIONS + "java_major", broken.resolve("bin").toString()));
    }
}
