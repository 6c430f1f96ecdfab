package touchline.ui.window;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * Named layouts as files in one directory ({@code ~/.config/touchline/layouts} by default;
 * tests pass their own). A name is reduced to safe file-name characters.
 */
public final class LayoutStore {

    static final String SUFFIX = ".layout";
    private final Path dir;
    private final LayoutCodec codec = new LayoutCodec();

    public LayoutStore(Path dir) {
        this.dir = dir;
    }

    public static Path defaultDir() {
        return Path.of(System.getProperty("user.home"), ".config", "touchline", "layouts");
    }

    public Path dir() {
        return dir;
    }

    static String fileName(String name) {
        String safe = name.strip().replaceAll("[^A-Za-z0-9._ -]", "_");
        if (safe.isEmpty() || safe.startsWith(".")) {
            safe = "layout" + safe;
        }
        return safe + SUFFIX;
    }

    public void save(String name, List<LayoutNode> windows) throws IOException {
        Files.createDirectories(dir);
        Path tmp = dir.resolve(fileName(name) + ".tmp");
        Files.writeString(tmp, codec.write(windows), StandardCharsets.UTF_8);
        Files.move(tmp, dir.resolve(fileName(name)), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    /** The layout, or empty when there is no such file; a damaged file yields what could be read. */
    public Optional<List<LayoutNode>> load(String name) throws IOException {
        Path p = dir.resolve(fileName(name));
        if (!Files.isRegularFile(p)) {
            return Optional.empty();
        }
        return Optional.of(codec.read(Files.readString(p, StandardCharsets.UTF_8)));
    }

    /**
     * Gives a saved layout another name; an existing layout of that name is never overwritten.
     *
     * @throws IOException with the reason in words: no such layout, the name is taken, the disk failed
     */
    public void rename(String from, String to) throws IOException {
        Path source = dir.resolve(fileName(from));
        Path target = dir.resolve(fileName(to));
        if (!Files.isRegularFile(source)) {
            throw new IOException("no layout \"" + from + "\"");
        }
        if (source.equals(target)) {
            return;
        }
        if (Files.exists(target)) {
            throw new IOException("a layout \"" + to + "\" exists already");
        }
        Files.move(source, target);
    }

    /** Deletes a saved layout; false when there was none of that name. */
    public boolean delete(String name) throws IOException {
        return Files.deleteIfExists(dir.resolve(fileName(name)));
    }

    public List<String> names() {
        List<String> out = new ArrayList<>();
        if (!Files.isDirectory(dir)) {
            return out;
        }
        try (Stream<Path> files = Files.list(dir)) {
            files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(SUFFIX))
                    .map(n -> n.substring(0, n.length() - SUFFIX.length())).sorted().forEach(out::add);
        } catch (IOException e) {
            // an unreadable directory simply lists nothing; saving will report the error
        }
        return out;
    }
}
