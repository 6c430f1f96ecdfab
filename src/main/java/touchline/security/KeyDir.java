package touchline.security;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The key directory (docs/security.md): {@code team.key} for the small robots' tags and the
 * CURVE key pairs of the NAO link ({@code nao-server.secret/.public}, {@code console.secret/.public}),
 * made with owner-only permissions (directory 0700, files 0600, the {@code .public} files 0644),
 * plus {@code console.counter}, the console's last tag counter, and {@code robots.boot}, the robots'
 * boots believed. The one place that
 * finds the directory, reads key files (checking that secret ones are the owner's only) and makes
 * keys, the CURVE pairs included (JeroMQ's Curve25519, valid libzmq keys); the NAO link takes its
 * part with {@code touchline.transport.nao.NaoClientKeys}.
 */
public final class KeyDir {

    public static final String TEAM_KEY = "team.key";
    public static final String NAO_SERVER_SECRET = "nao-server.secret";
    public static final String NAO_SERVER_PUBLIC = "nao-server.public";
    public static final String CONSOLE_SECRET = "console.secret";
    public static final String CONSOLE_PUBLIC = "console.public";
    public static final String COUNTER = "console.counter";
    /** The highest boot verified from each small robot ({@link RobotBoots}). */
    public static final String BOOTS = "robots.boot";
    /** The five key files {@link #create} writes (not the counter). */
    public static final List<String> FILES = List.of(TEAM_KEY, NAO_SERVER_SECRET, NAO_SERVER_PUBLIC, CONSOLE_SECRET, CONSOLE_PUBLIC);

    private static final Set<PosixFilePermission> OWNER_ONLY = PosixFilePermissions.fromString("rw-------");
    private static final Set<PosixFilePermission> READABLE = PosixFilePermissions.fromString("rw-r--r--");

    /** Serialises the file locks of this process: two channels of one JVM may not lock one file at once. */
    private static final Object LOCKS = new Object();

    private final Path dir;

    public KeyDir(Path dir) {
        this.dir = dir;
    }

    /** {@code --keys DIR}, else {@code TOUCHLINE_KEYS}, else {@code ${XDG_CONFIG_HOME:-$HOME/.config}/touchline/keys}. */
    public static KeyDir locate(Optional<Path> option, Map<String, String> env) {
        if (option.isPresent()) {
            return new KeyDir(option.get());
        }
        String fromEnv = env.get("TOUCHLINE_KEYS");
        if (fromEnv != null && !fromEnv.isBlank()) {
            return new KeyDir(Path.of(fromEnv));
        }
        String xdg = env.get("XDG_CONFIG_HOME");
        Path config = xdg != null && !xdg.isBlank() ? Path.of(xdg)
                : Path.of(env.getOrDefault("HOME", System.getProperty("user.home")), ".config");
        return new KeyDir(config.resolve("touchline").resolve("keys"));
    }

    public Path path() {
        return dir;
    }

    public Path file(String name) {
        return dir.resolve(name);
    }

    public boolean hasTeamKey() {
        return Files.isRegularFile(file(TEAM_KEY));
    }

    /** The team key, or a message saying what is wrong and how to recover. */
    public TeamKey teamKey() throws KeyException {
        return read(TEAM_KEY, true).teamKey();
    }

    /** A key file, checked for owner-only permissions when it holds a secret. */
    public KeyFile read(String name, boolean secret) throws KeyException {
        Path f = file(name);
        try {
            if (secret) {
                checkOwnerOnly(f);
            }
            return KeyFile.parse(f.toString(), Files.readString(f, StandardCharsets.UTF_8));
        } catch (NoSuchFileException e) {
            throw new KeyException(f + ": missing; make the team's keys with `touchline keys new` (or copy the"
                    + " team's key directory here, or name it with --keys DIR)");
        } catch (java.nio.charset.MalformedInputException e) {
            throw new KeyException(f + ": not UTF-8 text, corrupted; copy it again from the team's key directory or "
                    + KeyFile.RECOVER);
        } catch (IOException e) {
            throw new KeyException(f + ": cannot read (" + e.getMessage() + ")");
        }
    }

    private static void checkOwnerOnly(Path f) throws IOException, KeyException {
        try {
            Set<PosixFilePermission> p = Files.getPosixFilePermissions(f);
            for (PosixFilePermission open : List.of(PosixFilePermission.GROUP_READ, PosixFilePermission.GROUP_WRITE,
                    PosixFilePermission.OTHERS_READ, PosixFilePermission.OTHERS_WRITE)) {
                if (p.contains(open)) {
                    throw new KeyException(f + " is readable or writable by others (" + PosixFilePermissions.toString(p)
                            + "): a team key must be the owner's only; fix with `chmod 600 " + f + "`");
                }
            }
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system: nothing to check
        }
    }

    /** Writes all five files; refuses to overwrite any without {@code force}. Returns the new team key. */
    public TeamKey create(boolean force, SecureRandom random, Instant now) throws KeyException {
        try {
            if (!force) {
                for (String name : FILES) {
                    if (Files.exists(file(name))) {
                        throw new KeyException(file(name) + " exists: keys are not overwritten without --force (the"
                                + " robots flashed with the old team key stop accepting this console)");
                    }
                }
            }
            Files.createDirectories(dir);
            setPermissions(dir, PosixFilePermissions.fromString("rwx------"));
            TeamKey team = TeamKey.generate(random);
            String made = "# made by `touchline keys new` on " + now + "\n";
            write(TEAM_KEY, "# Touchline team key: the small robots' message tags (docs/security.md).\n" + made
                    + "# Needed by: every console of the team, and every small robot (`touchline keys show --c-header`).\n"
                    + "# Secret: never commit it, never send it in plain text.\n"
                    + "team-key = " + team.secretHex() + "\nkey-id = " + team.idHex() + "\n", true);
            String[] nao = new zmq.io.mechanism.curve.Curve().keypairZ85();
            String[] console = new zmq.io.mechanism.curve.Curve().keypairZ85();
            write(NAO_SERVER_SECRET, "# CURVE server key pair of the NAO link: goes onto the NAO (its RPC module).\n"
                    + made + "# Secret.\npublic-key = " + nao[0] + "\nsecret-key = " + nao[1] + "\n", true);
            write(NAO_SERVER_PUBLIC, "# The NAO's CURVE public key: what a console needs to talk to that NAO.\n" + made
                    + "public-key = " + nao[0] + "\n", false);
            write(CONSOLE_SECRET, "# This console's CURVE client key pair (the NAO link).\n" + made
                    + "# Secret: stays on this laptop.\npublic-key = " + console[0] + "\nsecret-key = " + console[1] + "\n", true);
            write(CONSOLE_PUBLIC, "# This console's CURVE public key: the NAO lists one such file per team laptop.\n"
                    + made + "public-key = " + console[0] + "\n", false);
            Files.deleteIfExists(file(COUNTER)); // a new key starts its own counter
            Files.deleteIfExists(file(BOOTS)); // and robots flashed with it their own boots
            return team;
        } catch (IOException e) {
            throw new KeyException("cannot write the keys into " + dir + ": " + e);
        }
    }

    private void write(String name, String text, boolean secret) throws IOException {
        writeFile(file(name), text.getBytes(StandardCharsets.UTF_8), secret);
    }

    /**
     * Writes {@code content} to {@code f} through a temporary file that has its permissions
     * (owner-only when {@code secret}) before any byte of the key is in it, then moved into place.
     * Also what {@code keys show --c-header/--blob} writes the firmware's key with.
     */
    public static void writeFile(Path f, byte[] content, boolean secret) throws IOException {
        Path tmp = f.resolveSibling(f.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        Set<PosixFilePermission> mode = secret ? OWNER_ONLY : READABLE;
        try {
            // created with its mode (open with O_EXCL and 0600): never readable by others, not even empty for a moment
            Files.createFile(tmp, PosixFilePermissions.asFileAttribute(mode));
        } catch (UnsupportedOperationException e) {
            Files.createFile(tmp); // not POSIX: the platform's defaults
        }
        setPermissions(tmp, mode); // the umask may have taken bits of a readable file away
        Files.write(tmp, content);
        Files.move(tmp, f, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }

    private static void setPermissions(Path p, Set<PosixFilePermission> perms) throws IOException {
        try {
            Files.setPosixFilePermissions(p, perms);
        } catch (UnsupportedOperationException e) {
            // not POSIX: the platform's defaults
        }
    }

    /**
     * The console's last tag counter in {@code console.counter}, shared by every console process of
     * this laptop: each counter is taken under a lock on the file (a damaged file counts as 0, the
     * clock rules; a read-only key directory leaves the counter to the clock and this run).
     */
    public CounterSource.Store counterStore() {
        Path f = file(COUNTER);
        return atLeast -> {
            long[] taken = {atLeast};
            try {
                update(f, text -> {
                    long last = parseOr(text.strip(), 0);
                    taken[0] = Math.max(atLeast, last + 1);
                    return String.format("%020d%n", taken[0]);
                });
            } catch (IOException e) {
                // read-only: counters still increase within this run (and by the clock)
            }
            return taken[0];
        };
    }

    /** The robots' boots believed ({@code robots.boot}: "robot N = boot" lines), shared like the counter. */
    public RobotBoots.Store bootStore() {
        Path f = file(BOOTS);
        return new RobotBoots.Store() {
            @Override
            public Map<Integer, Integer> load() {
                try {
                    return parseBoots(Files.readString(f));
                } catch (IOException | java.io.UncheckedIOException e) {
                    return Map.of(); // none kept yet, or unreadable: the boots of this run only
                }
            }

            @Override
            public void raise(int robotId, int boot) {
                try {
                    update(f, text -> {
                        Map<Integer, Integer> boots = new java.util.TreeMap<>(parseBoots(text));
                        boots.merge(robotId, boot, (a, b) -> Integer.compareUnsigned(a, b) >= 0 ? a : b);
                        StringBuilder out = new StringBuilder("# The highest boot number verified from each small robot"
                                + " (docs/security.md): older boots are refused.\n# Delete a line when that robot's flash"
                                + " was wiped.\n");
                        boots.forEach((r, b) -> out.append("robot ").append(r).append(" = ")
                                .append(Integer.toUnsignedString(b)).append('\n'));
                        return out.toString();
                    });
                } catch (IOException e) {
                    // read-only: the boot is believed for this run
                }
            }
        };
    }

    private static Map<Integer, Integer> parseBoots(String text) {
        Map<Integer, Integer> boots = new java.util.HashMap<>();
        for (String line : text.split("\n")) {
            String[] kv = line.split("=");
            String name = kv[0].strip();
            if (kv.length == 2 && name.startsWith("robot ")) {
                long robot = parseOr(name.substring(6).strip(), -1);
                long boot = parseOr(kv[1].strip(), -1);
                if (robot >= 0 && robot <= 255 && boot >= 0 && boot <= 0xFFFF_FFFFL) {
                    boots.put((int) robot, (int) boot);
                }
            }
        }
        return boots;
    }

    private static long parseOr(String s, long damaged) {
        try {
            return Long.parseLong(s);
        } catch (NumberFormatException e) {
            return damaged;
        }
    }

    /**
     * Rewrites a small file in place under an exclusive lock on it, for the console processes of
     * one laptop (the window and {@code touchline options}) to read and write it in turn; written
     * in place, not moved into place, since a lock belongs to the file it was taken on.
     */
    private static void update(Path f, java.util.function.UnaryOperator<String> change) throws IOException {
        synchronized (LOCKS) {
            try (java.nio.channels.FileChannel ch = java.nio.channels.FileChannel.open(f,
                    java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.READ,
                    java.nio.file.StandardOpenOption.WRITE);
                 java.nio.channels.FileLock lock = ch.lock()) {
                java.nio.ByteBuffer in = java.nio.ByteBuffer.allocate((int) Math.min(ch.size(), 64 * 1024));
                while (in.hasRemaining() && ch.read(in, in.position()) > 0) {
                    // read to the end (a small file)
                }
                String before = new String(in.array(), 0, in.position(), StandardCharsets.UTF_8);
                byte[] after = change.apply(before).getBytes(StandardCharsets.UTF_8);
                java.nio.ByteBuffer out = java.nio.ByteBuffer.wrap(after);
                while (out.hasRemaining()) {
                    ch.write(out, out.position());
                }
                ch.truncate(after.length);
            }
        }
    }
}
