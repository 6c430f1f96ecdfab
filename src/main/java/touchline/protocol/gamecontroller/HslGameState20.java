package touchline.protocol.gamecontroller;

/**
 * HSL RoboCupGameControlData version 20, 158 bytes: what the official HSL GameController
 * 7.x sends since RoboCup 2026 (7.0.0-rc.3, commit {@code a6bb00a}). RobotInfo is penalty,
 * secsTillUnpenalised, cautions (3 bytes); penalties include MOTION_IN_STOP and CAUTIONED.
 * 158 bytes is also the size of the 2014 version 8: only the version byte tells them apart.
 * {@link #trueData()} is the same layout with the header "RGTD" that registered monitors get.
 */
public final class HslGameState20 extends HslGameState {

    public static final int VERSION = 20;
    public static final int SIZE = FIXED_PART_SIZE + 2 * teamSize(false);

    /** Game state to robots, header "RGme". */
    public HslGameState20() {
        super("gc.hsl20", WireChecks.GAME_STATE_MAGIC, VERSION, false);
    }

    private HslGameState20(String kind) {
        super(kind, WireChecks.TRUE_DATA_MAGIC, VERSION, false);
    }

    /** The monitors' copy ("RGTD"): the true state, also during the 10 s of SET robots see after a whistle. */
    public static HslGameState20 trueData() {
        return new HslGameState20("gc.hsl20.truedata");
    }
}
