package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.security.KeyDir;
import touchline.security.KeyException;
import touchline.security.KeyFile;
import touchline.security.RobotKeyExport;
import touchline.security.TeamKey;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.Map;
import java.util.Optional;

/**
 * {@code touchline keys new|show}: the team's keys (docs/security.md). {@code new} writes the
 * team key and the NAO link's CURVE key pairs with owner-only permissions; {@code show} prints
 * the key-id and what each robot needs, or writes the firmware's C header or flash blob.
 */
@Command(name = "keys", mixinStandardHelpOptions = true,
        description = "Make or show the team's keys: small robots' message tags, the NAO link's CURVE keys.",
        subcommands = {KeysCommand.New.class, KeysCommand.Show.class})
public final class KeysCommand {

    private final Map<String, String> env;

    public KeysCommand() {
        this(System.getenv());
    }

    KeysCommand(Map<String, String> env) {
        this.env = env;
    }

    KeyDir dir(Path option) {
        return KeyDir.locate(Optional.ofNullable(option), env);
    }

    /** What both subcommands share: the parent (environment), {@code --keys DIR}, the output. */
    abstract static class Sub implements java.util.concurrent.Callable<Integer> {
        @CommandLine.ParentCommand
        KeysCommand parent;

        @Option(names = "--keys", paramLabel = "DIR", description = "key directory (default: $TOUCHLINE_KEYS,"
                + " else ~/.config/touchline/keys)")
        Path keys;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        KeyDir dir() {
            return parent.dir(keys);
        }
    }

    @Command(name = "new", mixinStandardHelpOptions = true,
            description = "Make a new team key and CURVE key pairs (refuses to overwrite without --force).")
    static final class New extends Sub {
        @Option(names = "--force", description = "overwrite existing keys (every robot then needs the new key)")
        boolean force;

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            KeyDir dir = dir();
            try {
                // The real clock, made once for this command (it has no console): the key's date.
                TeamKey key = dir.create(force, new SecureRandom(), new touchline.app.SystemClock().instant());
                out.printf("made team key %s and the NAO link's CURVE key pairs in %s (owner-only)%n", key.idHex(),
                        dir.path());
                out.println("next: `touchline keys show` says what each robot needs");
                out.flush();
                return 0;
            } catch (KeyException e) {
                spec.commandLine().getErr().println("touchline keys new: " + e.getMessage());
                return 1;
            }
        }
    }

    @Command(name = "show", mixinStandardHelpOptions = true,
            description = "Print the key-id and what each robot needs; or write the firmware's C header or blob.")
    static final class Show extends Sub {
        @CommandLine.ArgGroup(exclusive = true)
        Export export;

        static final class Export {
            @Option(names = "--c-header", paramLabel = "FILE", description = "write the team key as a C header for the firmware build")
            Path cHeader;

            @Option(names = "--blob", paramLabel = "FILE", description = "write the team key as a 40-byte blob to flash")
            Path blob;
        }

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            KeyDir dir = dir();
            try {
                TeamKey key = dir.teamKey();
                if (export != null && export.cHeader != null) {
                    KeyDir.writeFile(export.cHeader, RobotKeyExport.cHeader(key).getBytes(java.nio.charset.StandardCharsets.UTF_8), true);
                    out.printf("wrote the C header of team key %s to %s (secret: owner-only, keep it out of git)%n",
                            key.idHex(), export.cHeader);
                } else if (export != null && export.blob != null) {
                    KeyDir.writeFile(export.blob, RobotKeyExport.blob(key), true);
                    out.printf("wrote the %d-byte flash blob of team key %s to %s (secret: owner-only)%n",
                            RobotKeyExport.BLOB_SIZE, key.idHex(), export.blob);
                } else {
                    describe(out, dir, key);
                }
                out.flush();
                return 0;
            } catch (KeyException e) {
                err.println("touchline keys show: " + e.getMessage());
                return 1;
            } catch (IOException e) {
                err.println("touchline keys show: cannot write: " + e);
                return 1;
            }
        }

        private static void describe(PrintWriter out, KeyDir dir, TeamKey key) throws KeyException {
            out.printf("key directory %s%n", dir.path());
            out.printf("team key: key-id %s%n", key.idHex());
            out.printf("  small robots (firmware): `touchline keys show --c-header team_key.h` (build) or --blob FILE"
                    + " (flash); simulated robots: touchline-robot --team-key %s%n", dir.file(KeyDir.TEAM_KEY));
            out.printf("  other consoles of the team: a copy of %s (owner-only)%n", dir.file(KeyDir.TEAM_KEY));
            KeyFile server = dir.read(KeyDir.NAO_SERVER_PUBLIC, false);
            KeyFile console = dir.read(KeyDir.CONSOLE_PUBLIC, false);
            out.printf("NAO link (CURVE): the NAO needs %s and %s (public %s)%n", dir.file(KeyDir.NAO_SERVER_SECRET),
                    dir.file(KeyDir.CONSOLE_PUBLIC), console.curveKey("public-key").z85());
            out.printf("  this console uses %s and %s (NAO public %s)%n", dir.file(KeyDir.CONSOLE_SECRET),
                    dir.file(KeyDir.NAO_SERVER_PUBLIC), server.curveKey("public-key").z85());
        }

    }
}
