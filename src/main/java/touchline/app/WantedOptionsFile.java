package touchline.app;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;

/**
 * The debug options the user wants per robot ID, kept between runs in one properties file
 * ({@code ROBOT/OPTION=on}) beside the layouts. Written whole through a temporary file; a file
 * that cannot be read or written only costs the remembering: the reason is kept for the
 * status line and logged once.
 */
final class WantedOptionsFile {

    private final Path file;
    private volatile String problem = "";

    WantedOptionsFile(Path file) {
        this.file = file;
    }

    Path file() {
        return file;
    }

    /** What went wrong last (empty when nothing did). */
    String problem() {
        return problem;
    }

    Map<Integer, Set<String>> read() {
        Map<Integer, Set<String>> out = new TreeMap<>();
        if (!Files.isRegularFile(file)) {
            return out;
        }
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(r);
        } catch (IOException | IllegalArgumentException e) {
            fail("could not read the wanted debug options in " + file + ": " + e.getMessage());
            return out;
        }
        for (String key : p.stringPropertyNames()) {
            int slash = key.indexOf('/');
            if (slash <= 0 || slash == key.length() - 1 || !"on".equals(p.getProperty(key).trim())) {
                continue;
            }
            try {
                int robot = Integer.parseInt(key.substring(0, slash).trim());
                out.computeIfAbsent(robot, k -> new LinkedHashSet<>()).add(key.substring(slash + 1));
            } catch (NumberFormatException e) {
                fail("ignored \"" + key + "\" in " + file + ": not ROBOT/OPTION");
            }
        }
        return out;
    }

    synchronized void write(Map<Integer, Set<String>> wanted) {
        Properties p = new Properties();
        wanted.forEach((robot, names) -> names.forEach(n -> p.setProperty(robot + "/" + n, "on")));
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
            try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
                p.store(w, "Touchline: the debug options wanted per robot, switched on again at the next start");
            }
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            fail("could not remember the wanted debug options in " + file + ": " + e.getMessage());
        }
    }

    private void fail(String text) {
        if (!text.equals(problem)) {
            org.slf4j.LoggerFactory.getLogger(WantedOptionsFile.class).warn(text);
        }
        problem = text;
    }
}
