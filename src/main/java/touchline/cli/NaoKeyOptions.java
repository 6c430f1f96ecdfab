package touchline.cli;

import picocli.CommandLine.Option;
import touchline.transport.nao.KeyDirectory;
import touchline.transport.nao.KeyFileException;
import touchline.transport.nao.NaoClientKeys;

import java.nio.file.Path;

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
    NaoClientKeys load() throws KeyFileException {
        if (insecure) {
            return null;
        }
        Path dir = KeyDirectory.resolve(keys == null ? null : keys.toString());
        try {
            return NaoClientKeys.load(dir);
        } catch (KeyFileException e) {
            throw new KeyFileException(e.getMessage() + ". For an old robot side without keys: --insecure");
        }
    }
}
