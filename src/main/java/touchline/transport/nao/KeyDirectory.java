package touchline.transport.nao;

import java.nio.file.Path;
import java.util.Map;

/**
 * Where the console's key files live: the {@code --keys DIR} option when given, else the
 * environment variable {@code TOUCHLINE_KEYS}, else {@code ${XDG_CONFIG_HOME:-$HOME/.config}/touchline/keys}.
 */
public final class KeyDirectory {

    public static final String ENV = "TOUCHLINE_KEYS";

    private KeyDirectory() {
    }

    /**
     * @param option the {@code --keys} value, or null when not given
     * @param env    the environment (System.getenv() in the product)
     * @param home   the user's home directory (user.home)
     */
    public static Path resolve(String option, Map<String, String> env, String home) {
        if (option != null && !option.isBlank()) {
            return Path.of(option);
        }
        String fromEnv = env.get(ENV);
        if (fromEnv != null && !fromEnv.isBlank()) {
            return Path.of(fromEnv);
        }
        String xdg = env.get("XDG_CONFIG_HOME");
        Path config = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(home, ".config");
        return config.resolve("touchline").resolve("keys");
    }

    /** {@link #resolve(String, Map, String)} with this process's environment and home. */
    public static Path resolve(String option) {
        return resolve(option, System.getenv(), System.getProperty("user.home"));
    }
}
