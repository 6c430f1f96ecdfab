package touchline.protocol.gamecontroller;

/**
 * The set plays of the Humanoid Soccer League (HSL, 2026), as numbered on the wire of
 * versions 19 and 20 (offset 11). Each has a Humanoid League secondary state, the neutral form
 * of {@link GameControlData#secondaryState()}; a kick-off is not a set play on the wire (it is
 * NONE with the kicking team set).
 */
public enum HslSetPlay {
    NONE(0),
    DIRECT_FREE_KICK(4),
    INDIRECT_FREE_KICK(5),
    PENALTY_KICK(6),
    THROW_IN(9),
    GOAL_KICK(8),
    CORNER_KICK(7);

    private final int secondaryState;

    HslSetPlay(int secondaryState) {
        this.secondaryState = secondaryState;
    }

    /** The wire code (0–6). */
    public int wire() {
        return ordinal();
    }

    /** The neutral (HL v12 STATE2_*) code. */
    public int secondaryState() {
        return secondaryState;
    }

    /** The set play with this wire code, or null when the code is out of range. */
    public static HslSetPlay ofWire(int code) {
        HslSetPlay[] all = values();
        return code >= 0 && code < all.length ? all[code] : null;
    }

    /** The set play for a neutral secondary state; NONE for game phases (normal, shoot-out, overtime, timeout). */
    public static HslSetPlay ofSecondaryState(int secondaryState) {
        for (HslSetPlay p : values()) {
            if (p != NONE && p.secondaryState == secondaryState) {
                return p;
            }
        }
        return NONE;
    }
}
