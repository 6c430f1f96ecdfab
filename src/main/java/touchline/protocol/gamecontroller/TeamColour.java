package touchline.protocol.gamecontroller;

/**
 * Jersey colours as numbered by the SPL and HSL GameControllers (TEAM_* in the header), the
 * values of {@link TeamInfo#colour()} and {@link TeamInfo#goalkeeperColour()}.
 */
public enum TeamColour {
    BLUE, RED, YELLOW, BLACK, WHITE, GREEN, ORANGE, PURPLE, BROWN, GRAY;

    /** The colour with this wire code, or null when out of range. */
    public static TeamColour ofWire(int code) {
        TeamColour[] all = values();
        return code >= 0 && code < all.length ? all[code] : null;
    }
}
