package touchline.protocol.gamecontroller;

/**
 * One robot's entry in a game-state packet, in format-neutral form. Penalty codes are in the
 * Humanoid League v12 code space (0 none, 14 substitute, 15 manual, 30..35 HL penalties,
 * legacy SPL 1..11), extended by the HSL 2026 penalties 41..52 ({@link HslPenalty}); each
 * serializer translates them to its own wire codes.
 *
 * @param penalty             penalty code (HL v12 code space, HSL 41..52)
 * @param secsTillUnpenalised seconds until the penalty ends, 0 when not timed
 * @param warnings            number of warnings (HL v12, HSL v19)
 * @param yellowCards         yellow card count (HL v12), cautions (HSL v19/v20: a caution is the yellow card)
 * @param redCards            red card count (HL v12 only)
 * @param goalkeeper          whether this robot is its team's goalkeeper
 */
public record RobotInfo(int penalty, int secsTillUnpenalised, int warnings, int yellowCards, int redCards,
                        boolean goalkeeper) {

    public static final RobotInfo EMPTY = new RobotInfo(0, 0, 0, 0, 0, false);

    /** HSL name of the yellow-card count. */
    public int cautions() {
        return yellowCards;
    }

    public static RobotInfo penalised(int penalty, int secsTillUnpenalised) {
        return new RobotInfo(penalty, secsTillUnpenalised, 0, 0, 0, false);
    }
}
