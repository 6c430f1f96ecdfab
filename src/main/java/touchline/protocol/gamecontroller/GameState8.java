package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;

/**
 * RoboCupGameControlData version 8, 158 bytes: what a 2014 robot (SPL and HL) expects
 * (RoboCup-SPL/GameController tag RoboCup2014). u8 version, kick-off team given as a colour
 * with 2 = dropped ball, secondary state limited to 0–3 (set plays are sent as NORMAL),
 * 40-byte coach message, 2-byte RobotInfo × 11. In humanoid mode HL penalties 30..35 are
 * written as the 2014 HL codes 1..6.
 */
public final class GameState8 extends FixedSizeFormat {

    public static final int SIZE = 158;
    public static final int VERSION = 8;
    public static final int MAX_PLAYERS = 11;
    static final int COACH_MESSAGE_SIZE = 40;

    private final boolean humanoid;

    /** Humanoid League penalty codes (the default). */
    public GameState8() {
        this(true);
    }

    /** @param humanoid translate HL penalties to the 2014 HL codes 1..6 (false: SPL codes unchanged) */
    public GameState8(boolean humanoid) {
        super("gc.v8", VERSION, 1, SIZE);
        this.humanoid = humanoid;
    }

    @Override
    void encodeBody(GameControlData d, ByteBuffer b) {
        b.put((byte) d.packetNumber());
        b.put((byte) d.playersPerTeam());
        b.put((byte) d.state());
        b.put((byte) (d.firstHalf() ? 1 : 0));
        b.put((byte) LegacyCodes.kickOffColour(d));
        b.put((byte) (d.secondaryState() <= 3 ? d.secondaryState() : 0));
        b.put((byte) d.dropInTeam());
        b.putShort((short) d.dropInTime());
        b.putShort((short) d.secsRemaining());
        b.putShort((short) d.secondaryTime());
        for (TeamInfo t : d.teams()) {
            b.put((byte) t.teamNumber());
            b.put((byte) t.colour());
            b.put((byte) t.score());
            b.put((byte) t.penaltyShot());
            b.putShort((short) t.singleShots());
            b.position(b.position() + COACH_MESSAGE_SIZE);
            putRobot(b, t.coach());
            for (int p = 1; p <= MAX_PLAYERS; p++) {
                putRobot(b, t.player(p));
            }
        }
    }

    private void putRobot(ByteBuffer b, RobotInfo r) {
        b.put((byte) LegacyCodes.legacyPenalty(r.penalty(), humanoid));
        b.put((byte) r.secsTillUnpenalised());
    }

    @Override
    Decoded<GameControlData> decodeBody(ByteBuffer b) {
        int packetNumber = WireChecks.u8(b);
        int playersPerTeam = WireChecks.u8(b);
        int state = WireChecks.u8(b);
        boolean firstHalf = WireChecks.u8(b) != 0;
        int kickOffColour = WireChecks.u8(b);
        int secondary = WireChecks.u8(b);
        int dropInTeam = WireChecks.u8(b);
        int dropInTime = WireChecks.u16(b);
        int secsRemaining = b.getShort();
        int secondaryTime = b.getShort();
        List<TeamInfo> teams = new ArrayList<>(2);
        for (int t = 0; t < 2; t++) {
            int number = WireChecks.u8(b);
            int colour = WireChecks.u8(b);
            int score = WireChecks.u8(b);
            int penaltyShot = WireChecks.u8(b);
            int singleShots = WireChecks.u16(b);
            b.position(b.position() + COACH_MESSAGE_SIZE);
            RobotInfo coach = getRobot(b);
            List<RobotInfo> players = new ArrayList<>(MAX_PLAYERS);
            for (int p = 0; p < MAX_PLAYERS; p++) {
                players.add(getRobot(b));
            }
            teams.add(new TeamInfo(number, colour, 0, score, penaltyShot, singleShots, 0, 0, coach, players));
        }
        int kickOff = LegacyCodes.kickOffTeam(kickOffColour, teams.get(0).colour(), teams.get(0).teamNumber(),
                teams.get(1).colour(), teams.get(1).teamNumber());
        if (kickOff == -2) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD,
                    "kickOffTeam colour " + kickOffColour + " is neither team's colour nor DROPBALL (2)");
        }
        return Decoded.ok(new GameControlData(packetNumber, playersPerTeam, 0, 0, state, firstHalf, kickOff,
                secondary, 0, 0, dropInTeam, dropInTime, secsRemaining, secondaryTime, teams));
    }

    private RobotInfo getRobot(ByteBuffer b) {
        int penalty = LegacyCodes.neutralPenalty(WireChecks.u8(b), humanoid);
        return RobotInfo.penalised(penalty, WireChecks.u8(b));
    }
}
