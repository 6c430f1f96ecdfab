package touchline.model;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Properties;

/**
 * A league's rules as far as the console measures them: the team-message budget per game and
 * its size limit, the debug period robots keep during play, the traffic limit of the field
 * network, the length of a game. Profiles are data the user picks (samples/profiles/*.properties:
 * HSL 2026, SPL 2025, HL 2025, lab); a figure the rulebook has but the profile does not know is
 * {@link RuleLimit#UNKNOWN}, shown as such.
 *
 * @param name                   e.g. "HSL 2026"
 * @param teamMessageBudget      team messages a team may send per game
 * @param perAddedMinute         messages added to the budget per added minute
 * @param extraTime              messages added for extra time
 * @param maxTeamMessageBytes    the largest legal team message
 * @param debugPeriodMillis      a robot's debug period during play: one datagram per so many ms
 * @param halfSeconds            length of a half of the normal game
 * @param halves                 halves of the normal game
 * @param trafficBitsPerSecond   the team's wireless traffic limit
 * @param maxDebugPacketBytes    the largest debug datagram (UDP payload) during play
 * @param maxDebugFragments      the IP fragments a debug datagram may take during play
 */
public record RuleProfile(String name, RuleLimit teamMessageBudget, RuleLimit perAddedMinute, RuleLimit extraTime,
                          RuleLimit maxTeamMessageBytes, RuleLimit debugPeriodMillis, int halfSeconds, int halves,
                          RuleLimit trafficBitsPerSecond, RuleLimit maxDebugPacketBytes, RuleLimit maxDebugFragments) {

    /** Where the launcher's working directory keeps the profiles the user can pick by name. */
    public static final Path SAMPLES = Path.of("samples", "profiles");

    /** The profile a console uses when none is chosen. */
    public static final String DEFAULT = "hsl-2026";

    /** Reads a profile by name ("hsl-2026", from {@link #SAMPLES}) or by the path of a .properties file. */
    public static RuleProfile named(String nameOrPath) throws RuleProfileException {
        Path direct = Path.of(nameOrPath);
        Path file = nameOrPath.endsWith(".properties") ? direct : SAMPLES.resolve(nameOrPath + ".properties");
        return load(file);
    }

    public static RuleProfile load(Path file) throws RuleProfileException {
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(in);
        } catch (NoSuchFileException e) {
            throw new RuleProfileException("no rule profile at " + file + " (profiles: hsl-2026, spl-2025, hl-2025, lab"
                    + " in " + SAMPLES + ", or the path of a .properties file)");
        } catch (IOException | IllegalArgumentException e) {
            throw new RuleProfileException("cannot read the rule profile " + file + ": " + e.getMessage());
        }
        Fields f = new Fields(file, p);
        return new RuleProfile(f.text("name"), f.limit("team-messages.budget"), f.optionalLimit("team-messages.per-added-minute"),
                f.optionalLimit("team-messages.extra-time"), f.limit("team-messages.max-bytes"),
                f.debugPeriod(), (int) f.number("half.seconds"), (int) f.number("halves"),
                f.limit("traffic.bits-per-second"), f.optionalLimit("debug.max-packet-bytes"),
                f.optionalLimit("debug.max-fragments"));
    }

    /** Reads one profile's keys, naming the file and the key in every complaint. */
    private record Fields(Path file, Properties p) {

        String text(String key) throws RuleProfileException {
            String v = p.getProperty(key);
            if (v == null || v.isBlank()) {
                throw new RuleProfileException(file + ": '" + key + "' is missing");
            }
            return v.trim();
        }

        long number(String key) throws RuleProfileException {
            String v = text(key);
            try {
                long n = Long.parseLong(v);
                if (n < 0) {
                    throw new NumberFormatException();
                }
                return n;
            } catch (NumberFormatException e) {
                throw new RuleProfileException(file + ": '" + key + "' must be a whole number ≥ 0, not '" + v + "'");
            }
        }

        RuleLimit limit(String key) throws RuleProfileException {
            String v = text(key).toLowerCase(Locale.ROOT);
            return switch (v) {
                case "none" -> RuleLimit.NONE;
                case "unknown" -> RuleLimit.UNKNOWN;
                default -> RuleLimit.of(number(key));
            };
        }

        /**
         * "debug.period-ms"; a profile written before it (only "debug.packets-per-second") keeps
         * working: n a second is a period of 1000/n ms.
         */
        RuleLimit debugPeriod() throws RuleProfileException {
            if (p.getProperty("debug.period-ms") != null || p.getProperty("debug.packets-per-second") == null) {
                return limit("debug.period-ms");
            }
            RuleLimit perSecond = limit("debug.packets-per-second");
            return !perSecond.known() ? perSecond
                    : perSecond.value() == 0 ? RuleLimit.NONE : RuleLimit.of(1000 / perSecond.value());
        }

        RuleLimit optionalLimit(String key) throws RuleProfileException {
            return p.getProperty(key) == null ? RuleLimit.NONE : limit(key);
        }
    }
}
