package touchline.transport.nao;

import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class NaoLinkConfigTest {

    @Test
    void theShippedSampleLoadsCleanlyAndMatchesTheBuiltInDefaults() {
        NaoLinkConfig sample = NaoLinkConfig.load(Path.of("samples/nao.properties"));
        assertEquals(java.util.List.of(), sample.problems());
        NaoLinkConfig defaults = NaoLinkConfig.defaults();
        NaoCall setAngles = NaoCall.of("ALMotion", "setAngles", "HeadYaw", 0f, 0.5f);
        NaoCall posture = NaoCall.of("ALRobotPosture", "goToPosture", "Stand", 1f);
        NaoCall methods = NaoCall.of("ALMotion", "getMethodList");
        for (NaoLinkConfig c : new NaoLinkConfig[] {sample, defaults}) {
            assertEquals(200, c.minIntervalMillis(setAngles));
            assertEquals(0, c.minIntervalMillis(posture));
            assertEquals(15000, c.timeoutMillis(posture));
            assertEquals(2500, c.timeoutMillis(setAngles));
            assertTrue(c.isIdempotent(methods), "*.getMethodList applies to every module");
            assertFalse(c.isIdempotent(setAngles));
            assertEquals(2, c.retries());
        }
    }

    @Test
    void brokenEntriesAreReportedAndDefaultsStay() {
        NaoLinkConfig c = NaoLinkConfig.parse("""
                timeout.default=soon
                interval.ALMotion.setAngles=-5
                interval.noDot=100
                retries=99
                colour=blue
                idempotent=ALMemory.getData
                """, "nao.properties");
        assertEquals(5, c.problems().size(), c.problems().toString());
        assertTrue(c.problems().stream().allMatch(p -> p.startsWith("nao.properties: ")));
        assertEquals(NaoLinkConfig.DEFAULT_TIMEOUT_MS, c.defaultTimeoutMillis());
        assertEquals(0, c.minIntervalMillis(NaoCall.of("ALMotion", "setAngles")));
        assertEquals(NaoLinkConfig.DEFAULT_RETRIES, c.retries());
        assertTrue(c.isIdempotent(NaoCall.of("ALMemory", "getData", "k")));
    }

    @Test
    void anUnreadableFileGivesTheBuiltInDefaults() {
        NaoLinkConfig c = NaoLinkConfig.parse("interval.ALMotion.setAngles=\\uZZZZ\n", "bad.properties");
        assertEquals(1, c.problems().size(), c.problems().toString());
        assertTrue(c.problems().get(0).contains("built-in defaults"));
        assertEquals(200, c.minIntervalMillis(NaoCall.of("ALMotion", "setAngles")));
    }

    @Test
    void aMissingFileGivesDefaultsAndOneClearProblem() throws Exception {
        Path dir = Files.createTempDirectory("naocfg");
        NaoLinkConfig c = NaoLinkConfig.load(dir.resolve("absent.properties"));
        assertEquals(1, c.problems().size());
        assertTrue(c.problems().get(0).contains("cannot read"));
        assertEquals(200, c.minIntervalMillis(NaoCall.of("ALMotion", "setAngles")));
    }
}
