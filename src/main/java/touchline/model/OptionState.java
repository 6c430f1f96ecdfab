package touchline.model;

/**
 * One debug option of one robot as the views show it.
 *
 * @param kind        the robot's data kind number (a {@code DebugKind}); unknown numbers are kept
 * @param wanted      the user switched it on in the console
 * @param enabledOnRobot what the robot's last option list said
 * @param streaming   data for it arrived within the last two seconds
 * @param matchRank   its place in the match digest as the user chose it (1 = first), 0 = not "in the game"
 * @param matchRankOnRobot its place as the robot's last option list confirmed it, 0 = not in its digest
 */
public record OptionState(String name, String description, int kind, boolean wanted, boolean enabledOnRobot,
                          boolean streaming, int matchRank, int matchRankOnRobot) {

    /** Chosen "in the game" and the robot confirmed the place. */
    public boolean matchConfirmed() {
        return matchRank == matchRankOnRobot;
    }

    public boolean knownKind() {
        return touchline.proto.Fumanoid.DebugKind.forNumber(kind) != null && kind != 0;
    }

    public String kindName() {
        var k = touchline.proto.Fumanoid.DebugKind.forNumber(kind);
        return k == null || kind == 0 ? "unknown kind " + kind : k.name();
    }
}
