package touchline.cli;

import picocli.CommandLine.Option;
import touchline.security.KeyDir;
import touchline.security.KeyException;
import touchline.transport.nao.NaoClientKeys;

import java.nio.file.Path;
import java.util.Optional;

/**
 * The NAO link's security options, shared by every command that talks to a NAO: CURVE with the
 * keys in {@code --keys DIR} (default: {@code $TOUCHLINE_KEYS}, else
 * {@code ~/.config/touchline/keys}), or {@code --insecure} for old robots without keys.
 */
final class NaoKeyOptions {

    @Option(names = "--keys", paramLabel = "DIR",
            description = "key directory with console.secret and nao-server.public (default: $TOUCHLINE_KEYS, "
                    + "else ~/.config/touchline/keys)")
    Path keys;

    @Option(names = "--insecure",
            description = "talk to the NAO without CURVE encryption and without our key (old robot sides only: "
                    + "anyone on the network can then command that robot)")
    boolean insecure;

    /** The keys to use, or null with {@code --insecure}; a missing or broken key file is a clear error. */
    NaoClientKeys load() throws KeyException {
        if (insecure) {
            return null;
        }
        KeyDir dir = KeyDir.locate(Optional.ofNullable(keys), System.getenv());
        try {
            return NaoClientKeys.load(dir);
        } catch (KeyException e) {
            throw new KeyException(e.getMessage() + ". For an old robot side without keys: --insecure");
        }
    }
}
