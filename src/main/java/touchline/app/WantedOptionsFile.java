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
 * ({@code ROBOT/OPTION=on}) beside the layouts, with each robot's match items in order
 * ({@code game/ROBOT=OPTION,OPTION}; empty = chosen none). Written whole through a temporary file; a file
 * that cannot be read or written only costs the remembering: the reason is kept for the
 * status line and logged once.
 */
final class WantedOptionsFile {

    private final Path file;
    private volatile String problem = "";
    private Map<Integer, java.util.List<String>> writtenMatch = Map.of();

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

    private Properties load() {
        Properties p = new Properties();
        if (!Files.isRegularFile(file)) {
            return p;
        }
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(r);
        } catch (IOException | IllegalArgumentException e) {
            fail("could not read the wanted debug options in " + file + ": " + e.getMessage());
        }
        return p;
    }

    /** Each robot's match items, in order, as last kept. */
    synchronized Map<Integer, java.util.List<String>> readMatch() {
        Map<Integer, java.util.List<String>> out = new TreeMap<>();
        Properties p = load();
        for (String key : p.stringPropertyNames()) {
            if (!key.startsWith(GAME)) {
                continue;
            }
            try {
                String v = p.getProperty(key).trim();
                out.put(Integer.parseInt(key.substring(GAME.length()).trim()),
                        v.isEmpty() ? java.util.List.of() : java.util.List.of(v.split("\\s*,\\s*")));
            } catch (NumberFormatException e) {
                fail("ignored \"" + key + "\" in " + file + ": not game/ROBOT");
            }
        }
        writtenMatch = Map.copyOf(out);
        return out;
    }

    /** Writes the file when the match items changed since they were last read or written. */
    synchronized void keepMatch(Map<Integer, Set<String>> wanted, Map<Integer, java.util.List<String>> match) {
        if (!match.equals(writtenMatch)) {
            write(wanted, match);
        }
    }

    private static final String GAME = "game/";

    Map<Integer, Set<String>> read() {
        Map<Integer, Set<String>> out = new TreeMap<>();
        Properties p = load();
        for (String key : p.stringPropertyNames()) {
            if (key.startsWith(GAME)) {
                continue;
            }
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

    synchronized void write(Map<Integer, Set<String>> wanted, Map<Integer, java.util.List<String>> match) {
        Properties p = new Properties();
        wanted.forEach((robot, names) -> names.forEach(n -> p.setProperty(robot + "/" + n, "on")));
        match.forEach((robot, names) -> p.setProperty(GAME + robot, String.join(",", names)));
        writtenMatch = Map.copyOf(match);
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
