package touchline.security;

import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The text of a key file (docs/security.md): UTF-8, '#' comments, blank lines, other lines
 * {@code name = value}; the keys in it, checked: the team key (hex, with its key-id) and the
 * CURVE keys (Z85). Pure parsing with messages that name the file, the line and the way out;
 * {@link KeyDir} reads the files.
 */
public final class KeyFile {

    static final String RECOVER = "make new keys with `touchline keys new --force` and give them to the robots "
            + "(docs/security.md)";

    private final String name;
    private final Map<String, String> values;

    private KeyFile(String name, Map<String, String> values) {
        this.name = name;
        this.values = values;
    }

    /** @param name what the messages name: the file's path */
    public static KeyFile parse(String name, String text) throws KeyException {
        Map<String, String> values = new LinkedHashMap<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            int eq = line.indexOf('=');
            if (eq <= 0) {
                throw new KeyException(name + " line " + (i + 1) + ": not 'name = value' (found '" + abbreviate(line)
                        + "'), corrupted; " + RECOVER);
            }
            String key = line.substring(0, eq).strip();
            if (values.put(key, line.substring(eq + 1).strip()) != null) {
                throw new KeyException(name + " line " + (i + 1) + ": '" + key + "' appears twice, corrupted; " + RECOVER);
            }
        }
        return new KeyFile(name, values);
    }

    private static String abbreviate(String line) {
        return line.length() <= 20 ? line : line.substring(0, 20) + "…";
    }

    /** The value of {@code key}, or a clear error when the file has no such line. */
    public String value(String key) throws KeyException {
        String v = values.get(key);
        if (v == null) {
            throw new KeyException(name + ": no '" + key + " = ...' line (the wrong file, or corrupted); " + RECOVER);
        }
        return v;
    }

    /** The team key of a {@code team.key} file, checked against its {@code key-id}. */
    public TeamKey teamKey() throws KeyException {
        String hex = value("team-key");
        if (hex.length() != 2 * TeamKey.SIZE || !hex.chars().allMatch(KeyFile::isHex)) {
            throw new KeyException(name + ": team-key must be " + 2 * TeamKey.SIZE + " hex digits (" + TeamKey.SIZE
                    + " bytes), found " + hex.length() + " characters" + (hex.chars().allMatch(KeyFile::isHex) ? "" : " with non-hex ones"));
        }
        TeamKey key = new TeamKey(HexFormat.of().parseHex(hex.toLowerCase(java.util.Locale.ROOT)));
        String id = value("key-id");
        if (!id.equalsIgnoreCase(key.idHex())) {
            throw new KeyException(name + ": key-id " + id + " does not belong to this team-key (it would be "
                    + key.idHex() + "): the file was edited or damaged");
        }
        return key;
    }

    /** The CURVE key in line {@code key}, checked: 40 Z85 characters that decode to 32 bytes. */
    public CurveKey curveKey(String key) throws KeyException {
        return CurveKey.parse(value(key), name + ": " + key);
    }

    private static boolean isHex(int c) {
        return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    }
}
