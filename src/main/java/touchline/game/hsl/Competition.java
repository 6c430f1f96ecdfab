package touchline.game.hsl;

import java.util.Locale;

/**
 * The six competitions of the Humanoid Soccer League 2026 (config directories of the official
 * GameController 7.0.0 and 6.0.1): a division, sent as competitionType, and Foundation or
 * Advanced, which shows only in the number of players per team. All other parameters are the
 * same in the six.
 */
public enum Competition {
    SMALL_FOUNDATION(0, 4),
    SMALL_ADVANCED(0, 7),
    MIDDLE_FOUNDATION(1, 3),
    MIDDLE_ADVANCED(1, 5),
    LARGE_FOUNDATION(2, 3),
    LARGE_ADVANCED(2, 5);

    private final int type;
    private final int playersPerTeam;

    Competition(int type, int playersPerTeam) {
        this.type = type;
        this.playersPerTeam = playersPerTeam;
    }

    /** Wire competitionType: 0 SMALL, 1 MIDDLE, 2 LARGE. */
    public int type() {
        return type;
    }

    public int playersPerTeam() {
        return playersPerTeam;
    }

    /** The official config name, e.g. {@code middle_advanced}. */
    public String configName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The competition of a config name ({@code middle_advanced} or {@code middle-advanced}), null when unknown. */
    public static Competition parse(String name) {
        String n = name.trim().toLowerCase(Locale.ROOT).replace('-', '_');
        for (Competition c : values()) {
            if (c.configName().equals(n)) {
                return c;
            }
        }
        return null;
    }
}
