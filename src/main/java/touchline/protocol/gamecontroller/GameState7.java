package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * RoboCupGameControlData version 7, 116 bytes: the 2013 packet, which the 2014–2017 HL
 * GameController also sent every cycle as a "compatibility" packet ({@code toByteArray7()}).
 * u32 version, no packet number, kick-off team as a colour (2 = dropped ball), secondary state
 * 0–2, u32 secsRemaining, no secondary time, teams ordered by colour (blue first) with goal
 * colour always 1 and u16 penalty / u16 secsTillUnpenalised per player.
 */
public final class GameState7 extends FixedSizeFormat {

    public static final int SIZE = 116;
    public static final int VERSION = 7;
    public static final int MAX_PLAYERS = 11;
    static final int GOAL_COLOUR_YELLOW = 1;

    private final boolean humanoid;

    /** Humanoid League penalty codes (the default). */
    public GameState7() {
        this(true);
    }

    /** @param humanoid translate HL penalties to the legacy HL codes 1..6 (false: SPL codes unchanged) */
    public GameState7(boolean humanoid) {
        super("gc.v7", VERSION, 4, SIZE);
        this.humanoid = humanoid;
    }

    @Override
    void encodeBody(GameControlData d, ByteBuffer b) {
        b.put((byte) d.playersPerTeam());
        b.put((byte) d.state());
        b.put((byte) (d.firstHalf() ? 1 : 0));
        b.put((byte) LegacyCodes.kickOffColour(d));
        b.put((byte) (d.secondaryState() <= 2 ? d.secondaryState() : 0));
        b.put((byte) d.dropInTeam());
        b.putShort((short) d.dropInTime());
        b.putInt(d.secsRemaining());
        List<TeamInfo> byColour = new ArrayList<>(d.teams());
        byColour.sort(Comparator.comparingInt(TeamInfo::colour));
        for (TeamInfo t : byColour) {
            b.put((byte) t.teamNumber());
            b.put((byte) t.colour());
            b.put((byte) GOAL_COLOUR_YELLOW);
            b.put((byte) t.score());
            for (int p = 1; p <= MAX_PLAYERS; p++) {
                RobotInfo r = t.player(p);
                b.putShort((short) LegacyCodes.legacyPenalty(r.penalty(), humanoid));
                b.putShort((short) r.secsTillUnpenalised());
            }
        }
    }

    @Override
    Decoded<GameControlData> decodeBody(ByteBuffer b) {
        int playersPerTeam = WireChecks.u8(b);
        int state = WireChecks.u8(b);
        boolean firstHalf = WireChecks.u8(b) != 0;
        int kickOffColour = WireChecks.u8(b);
        int secondary = WireChecks.u8(b);
        int dropInTeam = WireChecks.u8(b);
        int dropInTime = WireChecks.u16(b);
        int secsRemaining = b.getInt();
        List<TeamInfo> teams = new ArrayList<>(2);
        for (int t = 0; t < 2; t++) {
            int number = WireChecks.u8(b);
            int colour = WireChecks.u8(b);
            WireChecks.u8(b); // goal colour: always yellow in the compatibility packet
            int score = WireChecks.u8(b);
            List<RobotInfo> players = new ArrayList<>(MAX_PLAYERS);
            for (int p = 0; p < MAX_PLAYERS; p++) {
                int penalty = LegacyCodes.neutralPenalty(WireChecks.u16(b), humanoid);
                players.add(RobotInfo.penalised(penalty, WireChecks.u16(b)));
            }
            teams.add(new TeamInfo(number, colour, 0, score, 0, 0, 0, 0, RobotInfo.EMPTY, players));
        }
        int kickOff = LegacyCodes.kickOffTeam(kickOffColour, teams.get(0).colour(), teams.get(0).teamNumber(),
                teams.get(1).colour(), teams.get(1).teamNumber());
        if (kickOff == -2) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD,
                    "kickOffTeam colour " + kickOffColour + " is neither team's colour nor DROPBALL (2)");
        }
        return Decoded.ok(new GameControlData(0, playersPerTeam, 0, 0, state, firstHalf, kickOff, secondary, 0, 0,
                dropInTeam, dropInTime, secsRemaining, 0, teams));
    }
}
