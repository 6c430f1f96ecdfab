package touchline.model;

/**
 * One debug option of one robot as the views show it.
 *
 * @param kind        the robot's data kind number (a {@code DebugKind}); unknown numbers are kept
 * @param wanted      the user switched it on in the console
 * @param enabledOnRobot what the robot's last option list said
 * @param streaming   data for it arrived within the last two seconds
 */
public record OptionState(String name, String description, int kind, boolean wanted, boolean enabledOnRobot,
                          boolean streaming) {

    public boolean knownKind() {
        return touchline.proto.Fumanoid.DebugKind.forNumber(kind) != null && kind != 0;
    }

    public String kindName() {
        var k = touchline.proto.Fumanoid.DebugKind.forNumber(kind);
        return k == null || kind == 0 ? "unknown kind " + kind : k.name();
    }
}
