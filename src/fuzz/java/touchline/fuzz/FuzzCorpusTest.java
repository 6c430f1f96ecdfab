package touchline.fuzz;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every finding the fuzzer ever kept ({@code src/test/resources/fuzz/<target>/}) and every
 * seed, replayed through its decoder: a finding that comes back fails here, in the normal suite.
 */
class FuzzCorpusTest {

    private static final Path CORPUS = Path.of("src/test/resources/fuzz");

    private final Targets targets = new Targets();

    // A guard only, so an input that makes a decoder loop fails instead of hanging the suite.
    private static final Duration GUARD = Duration.ofSeconds(30);

    @AfterEach
    void closeTargets() {
        targets.all().forEach(FuzzTarget::close);
    }

    @TestFactory
    Stream<DynamicTest> everyKeptFindingAndSeedStaysHarmless() throws IOException {
        List<DynamicTest> tests = new ArrayList<>();
        for (FuzzTarget t : targets.all()) {
            Path dir = CORPUS.resolve(t.name());
            if (Files.isDirectory(dir)) {
                try (Stream<Path> files = Files.list(dir)) {
                    for (Path f : files.filter(Files::isRegularFile).sorted().toList()) {
                        byte[] input = Files.readAllBytes(f);
                        tests.add(DynamicTest.dynamicTest(t.name() + "/" + f.getFileName(), () -> assertTimeoutPreemptively(GUARD, () -> t.accept(input))));
                    }
                }
            }
            List<byte[]> seeds = t.seeds();
            for (int i = 0; i < seeds.size(); i++) {
                byte[] input = seeds.get(i);
                tests.add(DynamicTest.dynamicTest(t.name() + " seed " + i, () -> assertTimeoutPreemptively(GUARD, () -> t.accept(input))));
            }
        }
        return tests.stream();
    }

    @Test
    void everyTargetHasSeedsAndADistinctName() {
        List<String> names = targets.all().stream().map(FuzzTarget::name).toList();
        assertTrue(names.size() == names.stream().distinct().count(), names.toString());
        for (FuzzTarget t : targets.all()) {
            assertFalse(t.seeds().isEmpty(), t.name() + " has no seeds");
        }
    }

    @Test
    void everyCorpusDirectoryBelongsToATarget() throws IOException {
        if (!Files.isDirectory(CORPUS)) {
            return;
        }
        try (Stream<Path> dirs = Files.list(CORPUS)) {
            for (Path d : dirs.toList()) {
                assertTrue(targets.named(d.getFileName().toString()).isPresent(), "no target replays " + d);
            }
        }
    }
}
