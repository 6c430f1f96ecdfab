package touchline.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;
import java.util.Set;

/**
 * Where {@code touchline serve} takes its viewers' token from: {@code --token T} (visible to
 * anyone who lists the processes), {@code --token-file F} (the first line of a file only its
 * owner may read or write, mode 0600 or stricter), or the environment ({@link #ENV}); at most one
 * of the options, and either wins over the environment. None: no token (loopback) or a
 * generated one.
 */
final class TokenChoice {

    /** The environment variable a token may come from. */
    static final String ENV = "TOUCHLINE_SERVE_TOKEN";
    /** What is read of a token file: its first line is the token, and a token is short. */
    static final int MAX_FILE_BYTES = 4096;

    private static final Set<PosixFilePermission> OTHERS = Set.of(PosixFilePermission.GROUP_READ,
            PosixFilePermission.GROUP_WRITE, PosixFilePermission.GROUP_EXECUTE, PosixFilePermission.OTHERS_READ,
            PosixFilePermission.OTHERS_WRITE, PosixFilePermission.OTHERS_EXECUTE);

    private final String option;
    private final Path file;
    private final Map<String, String> env;

    TokenChoice(String option, Path file, Map<String, String> env) {
        this.option = option;
        this.file = file;
        this.env = env;
    }

    /** The token, or null for none given; a StartFailure (exit 2) for a file that may not or cannot be used. */
    String token() throws StartFailure {
        if (option != null && file != null) {
            throw StartFailure.badInput("--token and --token-file contradict each other: choose one.");
        }
        if (option != null) {
            return nonEmpty(option, "--token");
        }
        if (file != null) {
            return fromFile();
        }
        String fromEnv = env.get(ENV);
        return fromEnv == null ? null : nonEmpty(fromEnv.strip(), "$" + ENV);
    }

    private String fromFile() throws StartFailure {
        try {
            Set<PosixFilePermission> mode = Files.getPosixFilePermissions(file);
            if (mode.stream().anyMatch(OTHERS::contains)) {
                throw StartFailure.badInput("the token file " + file + " may be read or changed by others (mode "
                        + PosixFilePermissions.toString(mode) + "): `chmod 600 " + file + "` and start again.");
            }
        } catch (UnsupportedOperationException e) {
            // not POSIX: the platform's own access rules protect it
        } catch (IOException e) {
            throw StartFailure.badInput("cannot read the token file " + file + ": " + e.getMessage());
        }
        try (java.io.InputStream in = Files.newInputStream(file)) {
            String text = new String(in.readNBytes(MAX_FILE_BYTES), java.nio.charset.StandardCharsets.UTF_8);
            return nonEmpty(text.lines().findFirst().orElse("").strip(), "the token file " + file);
        } catch (IOException e) {
            throw StartFailure.badInput("cannot read the token file " + file + ": " + e.getMessage());
        }
    }

    private static String nonEmpty(String token, String where) throws StartFailure {
        if (token.isEmpty()) {
            throw StartFailure.badInput(where + " gives an empty token: give one, or none to serve this machine only.");
        }
        return token;
    }
}
