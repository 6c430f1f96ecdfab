package touchline.protocol.gamecontroller;

/**
 * HSL RoboCupGameControlData version 19, 198 bytes: what the official HSL GameController
 * 6.0.0 / 6.0.1 sent (German Open 2026, tag {@code v6.0.1}). RobotInfo is penalty,
 * secsTillUnpenalised, warnings, cautions (4 bytes; 6.0.x never set the last two); penalties
 * are numbered without MOTION_IN_STOP and CAUTIONED. {@link #trueData()} is the monitors'
 * "RGTD" copy.
 */
public final class HslGameState19 extends HslGameState {

    public static final int VERSION = 19;
    public static final int SIZE = FIXED_PART_SIZE + 2 * teamSize(true);

    /** Game state to robots, header "RGme". */
    public HslGameState19() {
        super("gc.hsl19", WireChecks.GAME_STATE_MAGIC, VERSION, true);
    }

    private HslGameState19(String kind) {
        super(kind, WireChecks.TRUE_DATA_MAGIC, VERSION, true);
    }

    /** The monitors' copy ("RGTD"): the true state, also during the 10 s of SET robots see after a whistle. */
    public static HslGameState19 trueData() {
        return new HslGameState19("gc.hsl19.truedata");
    }
}
