package touchline;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code ./touchline test} runs the suite with {@code CI=true}, so a test whose requirement is
 * missing fails instead of skipping (docs/testing.md) on a developer's machine too, not only under
 * {@code .ci/run}. Run by bash with a stand-in {@code mvn} that reports what it was given.
 */
class LauncherTestCommandTest {

    @TempDir
    Path dir;

    @Test
    void theTestCommandExportsCiTrue() throws Exception {
        Path mvn = Files.writeString(dir.resolve("mvn"), "#!/bin/sh\necho \"mvn saw CI=${CI:-unset}\"\n");
        Files.setPosixFilePermissions(mvn, PosixFilePermissions.fromString("rwxr-xr-x"));
        ProcessBuilder pb = new ProcessBuilder("bash", "./touchline", "test", "--quick").redirectErrorStream(true);
        pb.environment().remove("CI");
        pb.environment().put("PATH", dir + ":" + System.getenv("PATH"));
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(30, TimeUnit.SECONDS), out);
        assertEquals(0, p.exitValue(), out);
        assertTrue(out.contains("mvn saw CI=true"), out);
    }
}
