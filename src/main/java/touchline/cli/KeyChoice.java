package touchline.cli;

import touchline.security.CounterSource;
import touchline.security.KeyDir;
import touchline.security.KeyException;
import touchline.security.LinkSecurity;
import touchline.security.RobotBoots;

import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;

/**
 * Which team key a listening command uses: none with {@code --insecure}; the directory of
 * {@code --keys} (which must hold a good team.key); else the default directory when it has a
 * team.key, else none (lab mode). Tells the user on stderr which it is.
 */
final class KeyChoice {

    private final Path option;
    private final boolean insecure;
    private final Map<String, String> env;

    KeyChoice(Path option, boolean insecure, Map<String, String> env) {
        this.option = option;
        this.insecure = insecure;
        this.env = env;
    }

    LinkSecurity security() throws StartFailure {
        if (insecure) {
            if (option != null) {
                throw StartFailure.badInput("--insecure and --keys contradict each other: choose one.");
            }
            System.err.println("keys: --insecure: nothing sent to the robots is tagged, nothing they send is checked");
            return LinkSecurity.off();
        }
        KeyDir dir = KeyDir.locate(Optional.ofNullable(option), env);
        if (option == null && !dir.hasTeamKey()) {
            System.err.println("keys: no team key in " + dir.path() + ": lab mode (nothing tagged or checked); make"
                    + " one with `touchline keys new`");
            return LinkSecurity.off();
        }
        try {
            // The real clock, made here once: the keys are chosen before any console exists.
            LinkSecurity s = LinkSecurity.with(dir.teamKey(),
                    new CounterSource(new touchline.app.SystemClock()::nowMicros, dir.counterStore()),
                    new RobotBoots(dir.bootStore()));
            System.err.println("keys: " + s.describe() + " (" + dir.path() + ")");
            return s;
        } catch (KeyException e) {
            throw StartFailure.badInput(e.getMessage() + ". To run without keys: --insecure");
        }
    }
}
