package touchline.protocol.gamecontroller;

/**
 * The penalties of the Humanoid Soccer League (HSL, 2026) with their wire codes in version 19
 * (GameController 6.0.x) and version 20 (7.x), which number them differently, and their neutral
 * code in {@link RobotInfo#penalty()} (41..52; NONE and SUBSTITUTE share the HL codes 0 and 14).
 * A penalty a version cannot name (v19 has no MOTION_IN_STOP or CAUTIONED) and the older
 * leagues' penalties without an HSL twin are written as PICK_UP, so the robot stays off the
 * field instead of being told it may play.
 */
public enum HslPenalty {
    NONE(0, 0, 0),
    ILLEGAL_POSITIONING(1, 1, 41),
    MOTION_IN_SET(2, 2, 42),
    MOTION_IN_STOP(-1, 3, 43),
    LOCAL_GAME_STUCK(3, 4, 44),
    INCAPABLE_ROBOT(4, 5, 45),
    PICK_UP(5, 6, 46),
    BALL_HOLDING(6, 7, 47),
    LEAVING_THE_FIELD(7, 8, 48),
    PLAYING_WITH_ARMS_HANDS(8, 9, 49),
    PUSHING(9, 10, 50),
    CAUTIONED(-1, 11, 51),
    SENT_OFF(10, 12, 52),
    SUBSTITUTE(11, 13, 14);

    private final int v19;
    private final int v20;
    private final int neutral;

    HslPenalty(int v19, int v20, int neutral) {
        this.v19 = v19;
        this.v20 = v20;
        this.neutral = neutral;
    }

    /** The code in the given protocol version (19 or 20), PICK_UP's for a penalty v19 lacks. */
    public int wire(int version) {
        int code = version == 19 ? v19 : v20;
        return code >= 0 ? code : PICK_UP.wire(version);
    }

    public int neutral() {
        return neutral;
    }

    /** The penalty with this wire code in {@code version}, or null when the code is unknown there. */
    public static HslPenalty ofWire(int version, int code) {
        for (HslPenalty p : values()) {
            if ((version == 19 ? p.v19 : p.v20) == code && code >= 0) {
                return p;
            }
        }
        return null;
    }

    /** The HSL penalty for a neutral code; HL penalties map to their nearest HSL rule. */
    public static HslPenalty ofNeutral(int code) {
        for (HslPenalty p : values()) {
            if (p.neutral == code) {
                return p;
            }
        }
        return switch (code) {
            case 30 -> PLAYING_WITH_ARMS_HANDS; // ball manipulation
            case 31 -> PUSHING;                 // physical contact
            case 32, 33 -> ILLEGAL_POSITIONING; // illegal attack / defence
            case 35 -> INCAPABLE_ROBOT;         // service
            default -> PICK_UP;                 // pickup/incapable, manual, SPL codes
        };
    }
}
