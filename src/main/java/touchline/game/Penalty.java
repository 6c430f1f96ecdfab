package touchline.game;

import java.util.Locale;

/**
 * A Humanoid League penalty with its v12 wire code. Timed penalties count down
 * {@link LeagueParams#penaltySeconds()} and end by themselves; MANUAL (a robot asked for it,
 * or the referee set it by hand) and SUBSTITUTE last until lifted.
 */
public enum Penalty {
    NONE(0, false),
    SUBSTITUTE(14, false),
    MANUAL(15, false),
    BALL_MANIPULATION(30, true),
    PHYSICAL_CONTACT(31, true),
    ILLEGAL_ATTACK(32, true),
    ILLEGAL_DEFENSE(33, true),
    PICKUP_OR_INCAPABLE(34, true),
    SERVICE(35, true);

    private final int code;
    private final boolean timed;

    Penalty(int code, boolean timed) {
        this.code = code;
        this.timed = timed;
    }

    public int code() {
        return code;
    }

    public boolean timed() {
        return timed;
    }

    /** Parses a name such as {@code physical_contact} (case-insensitive), or null. */
    public static Penalty parse(String name) {
        try {
            return valueOf(name.trim().toUpperCase(Locale.ROOT).replace('-', '_'));
        } catch (IllegalArgumentException e) {
            return null;
        }
    }
}
