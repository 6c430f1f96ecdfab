package touchline.app;

import org.junit.jupiter.api.Test;
import touchline.transport.UdpBackend;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The version the build writes from pom.xml, and the lines the window and --version show. */
class ProductVersionTest {

    @Test
    void theRunningClassesCarryThePomsVersion() throws Exception {
        Matcher m = Pattern.compile("<artifactId>touchline</artifactId>\\s*<version>([^<]+)</version>")
                .matcher(Files.readString(Path.of("pom.xml")));
        assertTrue(m.find(), "pom.xml names its version");
        assertEquals(m.group(1), ProductVersion.ofThisBuild().version());
        assertEquals("Touchline " + m.group(1), ProductVersion.ofThisBuild().title());
    }

    @Test
    void theChangelogHasAnEntryForThisVersion() throws Exception {
        String changelog = Files.readString(Path.of("CHANGELOG.md"));
        assertTrue(changelog.contains("## [" + ProductVersion.ofThisBuild().version() + "]"),
                "CHANGELOG.md has a section for " + ProductVersion.ofThisBuild().version());
    }

    @Test
    void anUnfilteredOrMissingResourceIsUnknownNotAPlaceholder() throws Exception {
        assertEquals("unknown", ProductVersion.read(null).version());
        assertEquals("unknown", ProductVersion.read(stream("version=${project.version}\n")).version());
        assertEquals("1.2.3", ProductVersion.read(stream("version=1.2.3\n")).version());
    }

    @Test
    void theReportSaysTheFallbacksInUse() {
        RuntimeReport portable = new RuntimeReport(new ProductVersion("0.5.0"), "Java 17", "Mac OS X 14 aarch64",
                UdpBackend.choose("auto", false, "not Linux"), "real-time priority only on Linux, this is Mac OS X");
        assertEquals(java.util.List.of("Touchline 0.5.0", "Java 17, Mac OS X 14 aarch64",
                "UDP transport: NIO (portable fallback, epoll not available here: not Linux)",
                "GameController sender: normal priority (real-time priority only on Linux, this is Mac OS X)"), portable.lines());
        assertEquals("NIO · normal priority", portable.portability());
        RuntimeReport linux = new RuntimeReport(new ProductVersion("0.5.0"), "Java 17", "Linux 6.1 amd64",
                UdpBackend.choose("auto", true, ""), "");
        assertEquals("epoll + recvmmsg · real-time capable", linux.portability());
    }

    private static ByteArrayInputStream stream(String s) {
        return new ByteArrayInputStream(s.getBytes(StandardCharsets.ISO_8859_1));
    }
}
