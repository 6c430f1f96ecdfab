package touchline.ui.window;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Properties;

/**
 * One small properties file of the user's settings (window places, the GameController tab's
 * last setup), written whole through a temporary file so a crash never leaves half of it. A
 * file that cannot be read or written only costs the remembering: logged once, never shown
 * as an error.
 */
public final class SettingsFile {

    private static final Logger LOG = LoggerFactory.getLogger(SettingsFile.class);

    private final Path file;
    private final String what;
    private boolean warned;

    /** @param what what the file remembers, for the log, e.g. "the window sizes" */
    public SettingsFile(Path file, String what) {
        this.file = file;
        this.what = what;
    }

    public Path file() {
        return file;
    }

    /** The remembered values; empty when there are none or they cannot be read. */
    public synchronized Properties read() {
        Properties p = new Properties();
        if (Files.isRegularFile(file)) {
            try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
                p.load(r);
            } catch (IOException | IllegalArgumentException e) {
                warnOnce("could not read " + what + " in " + file + ": " + e);
            }
        }
        return p;
    }

    public synchronized void write(Properties p, String comment) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
            try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
                p.store(w, comment);
            }
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            warnOnce("could not remember " + what + " in " + file + ": " + e);
        }
    }

    private void warnOnce(String text) {
        if (!warned) {
            warned = true;
            LOG.warn(text);
        }
    }
}
