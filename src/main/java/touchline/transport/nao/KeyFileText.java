package touchline.transport.nao;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.ByteBuffer;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One key file as the console's key tools write it (docs/security.md, "Key files"): UTF-8 text,
 * lines starting with {@code #} are comments, blank lines are ignored, every other line is
 * {@code name = value}. Anything else makes the file corrupted, with the line number said.
 */
public final class KeyFileText {

    static final String RECOVER = "make new keys with `touchline keys new --force` and give them to the robots "
            + "(docs/security.md)";

    private final Path file;
    private final Map<String, String> values;

    private KeyFileText(Path file, Map<String, String> values) {
        this.file = file;
        this.values = values;
    }

    /** Reads and parses {@code file}. */
    public static KeyFileText read(Path file) throws KeyFileException {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new KeyFileException(file + ": missing; " + RECOVER);
        } catch (IOException e) {
            throw new KeyFileException(file + ": cannot read (" + e.getMessage() + ")");
        }
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new KeyFileException(file + ": not UTF-8 text, corrupted; " + RECOVER);
        }
        return parse(file, text);
    }

    static KeyFileText parse(Path file, String text) throws KeyFileException {
        Map<String, String> values = new LinkedHashMap<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            int eq = line.indexOf('=');
            if (eq <= 0) {
                throw new KeyFileException(file + " line " + (i + 1) + ": not 'name = value', corrupted; " + RECOVER);
            }
            values.put(line.substring(0, eq).strip(), line.substring(eq + 1).strip());
        }
        return new KeyFileText(file, values);
    }

    public Path file() {
        return file;
    }

    /** The value of {@code name}, or a clear error when the file has no such line. */
    public String value(String name) throws KeyFileException {
        String v = values.get(name);
        if (v == null) {
            throw new KeyFileException(file + ": no '" + name + " = ...' line (the wrong file, or corrupted); "
                    + RECOVER);
        }
        return v;
    }

    /** The CURVE key in line {@code name}, checked: 40 Z85 characters that decode to 32 bytes. */
    public CurveKey curveKey(String name) throws KeyFileException {
        return CurveKey.parse(value(name), file + ": " + name);
    }
}
