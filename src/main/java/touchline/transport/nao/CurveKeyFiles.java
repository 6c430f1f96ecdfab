package touchline.transport.nao;

import zmq.io.mechanism.curve.Curve;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.List;

/**
 * Writes the four CURVE key files of the NAO link into a key directory (docs/security.md):
 * {@code nao-server.secret} and {@code nao-server.public} (the NAO's key pair), {@code console.secret}
 * and {@code console.public} (this console's). Key pairs come from JeroMQ's Curve25519
 * ({@link Curve#keypairZ85()}), valid libzmq CURVE keys. The directory is made mode 0700, secret
 * files 0600, public files 0644. The demo uses it for its own key directory; the key tool
 * ({@code touchline keys new}) writes the same files.
 */
public final class CurveKeyFiles {

    public static final List<String> FILES = List.of("nao-server.secret", "nao-server.public", "console.secret",
            "console.public");

    private final Curve curve = new Curve();

    /**
     * Writes the four files.
     *
     * @param overwrite false: refuses (FileAlreadyExistsException) when any of them exists
     */
    public void write(Path dir, boolean overwrite) throws IOException {
        if (!overwrite) {
            for (String f : FILES) {
                if (Files.exists(dir.resolve(f))) {
                    throw new FileAlreadyExistsException(dir.resolve(f).toString(), null,
                            "a key file is already there (--force replaces every key: robots then need the new ones)");
                }
            }
        }
        Files.createDirectories(dir);
        setPermissions(dir, "rwx------");
        String[] server = curve.keypairZ85();
        String[] console = curve.keypairZ85();
        String made = "# made " + Instant.now() + " by Touchline\n";
        write(dir.resolve("nao-server.secret"), "# The NAO robot side's CURVE key pair: copy onto the NAO only "
                + "(touchline-nao-sim --curve-secret). Keep secret.\n" + made + pair(server), "rw-------");
        write(dir.resolve("nao-server.public"), "# The NAO's CURVE public key: every console that talks to that "
                + "NAO needs it.\n" + made + "public-key = " + server[0] + "\n", "rw-r--r--");
        write(dir.resolve("console.secret"), "# This console's CURVE key pair (the NAO link's client keys). "
                + "Keep secret, stays on this laptop.\n" + made + pair(console), "rw-------");
        write(dir.resolve("console.public"), "# This console's CURVE public key: the NAO needs it to let this "
                + "console in (touchline-nao-sim --curve-clients).\n" + made + "public-key = " + console[0] + "\n",
                "rw-r--r--");
    }

    private static String pair(String[] keys) {
        return "public-key = " + keys[0] + "\nsecret-key = " + keys[1] + "\n";
    }

    private static void write(Path file, String text, String permissions) throws IOException {
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        Files.createFile(tmp);
        setPermissions(tmp, permissions);
        Files.writeString(tmp, text, StandardCharsets.UTF_8, StandardOpenOption.TRUNCATE_EXISTING);
        Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }

    private static void setPermissions(Path path, String permissions) throws IOException {
        try {
            Files.setPosixFilePermissions(path, PosixFilePermissions.fromString(permissions));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system (Windows): the user's profile directory protects the files
        }
    }
}
