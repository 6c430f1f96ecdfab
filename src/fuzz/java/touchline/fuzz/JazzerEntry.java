package touchline.fuzz;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The entry point Jazzer calls for every input: the target named by the system property
 * {@code touchline.fuzz.target}. Whatever the target throws is a finding. When
 * {@code touchline.fuzz.seeds} names a directory, the target's seeds are written there first,
 * so the fuzzer starts from well-formed inputs (Jazzer reads its corpus after this runs).
 */
public final class JazzerEntry {

    private static FuzzTarget target;

    private JazzerEntry() {
    }

    public static void fuzzerInitialize() {
        String name = System.getProperty("touchline.fuzz.target", "");
        target = new Targets().named(name)
                .orElseThrow(() -> new IllegalArgumentException("no fuzz target named '" + name + "'"));
        target.prepare();
        String seeds = System.getProperty("touchline.fuzz.seeds");
        if (seeds != null) {
            write(Path.of(seeds), target.seeds());
        }
    }

    public static void fuzzerTestOneInput(byte[] input) {
        target.accept(input);
    }

    private static void write(Path dir, List<byte[]> seeds) {
        try {
            Files.createDirectories(dir);
            for (int i = 0; i < seeds.size(); i++) {
                Files.write(dir.resolve(String.format("seed-%02d", i)), seeds.get(i));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
