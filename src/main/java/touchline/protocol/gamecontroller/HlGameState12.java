package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;

/**
 * Humanoid League RoboCupGameControlData version 12 in its 688-byte layout (April 2021 on;
 * RoboCup-Humanoid-TC/GameController v2024.1 {@code RoboCupGameControlData.h}): u16 version,
 * 332-byte TeamInfo with a 253-byte coach message, 6-byte RobotInfo × 11. A dropped ball is
 * written as {@code 0x80} like the Java GameController 2017–2024 (configurable to 255, the
 * value of the header and of the 2025 Rust GameController). {@link #legacy640()} is the layout
 * that carried the same version number from 2017-06 to 2021-04: 4-byte RobotInfo without
 * warnings and goalkeeper flag, 640 bytes.
 */
public final class HlGameState12 extends FixedSizeFormat {

    public static final int SIZE = 688;
    public static final int VERSION = 12;
    public static final int MAX_PLAYERS = 11;
    static final int COACH_MESSAGE_SIZE = 253;
    static final int TEAM_SIZE = 332;
    public static final int LEGACY_SIZE = 640;

    private final int dropBallByte;
    private final boolean sixByteRobotInfo;

    /** The Java GameController's encoding (dropped ball = 0x80). */
    public HlGameState12() {
        this(0x80);
    }

    /** @param dropBallByte kickOffTeam byte for a dropped ball: 0x80 (Java GC) or 255 (header, Rust GC) */
    public HlGameState12(int dropBallByte) {
        this("gc.hl12", dropBallByte, true);
    }

    private HlGameState12(String kind, int dropBallByte, boolean sixByteRobotInfo) {
        super(kind, VERSION, 2, sixByteRobotInfo ? SIZE : LEGACY_SIZE);
        this.dropBallByte = dropBallByte & 0xFF;
        this.sixByteRobotInfo = sixByteRobotInfo;
    }

    /** HL v12 as sent 2017-06 … 2021-04: 640 bytes, RobotInfo = penalty, secs, yellow, red. */
    public static HlGameState12 legacy640() {
        return new HlGameState12("gc.hl12-640", 0x80, false);
    }

    @Override
    void encodeBody(GameControlData d, ByteBuffer b) {
        b.put((byte) d.packetNumber());
        b.put((byte) d.playersPerTeam());
        b.put((byte) d.gameType());
        b.put((byte) d.state());
        b.put((byte) (d.firstHalf() ? 1 : 0));
        b.put((byte) (d.kickOffTeam() == GameControlData.DROP_BALL ? dropBallByte : d.kickOffTeam()));
        b.put((byte) d.secondaryState());
        b.put((byte) d.setPlayTeam());
        b.put((byte) d.setPlayMode());
        b.put((byte) 0);
        b.put((byte) 0);
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
            b.put((byte) t.coachSequence());
            b.position(b.position() + COACH_MESSAGE_SIZE);
            putRobot(b, t.coach());
            for (int p = 1; p <= MAX_PLAYERS; p++) {
                putRobot(b, t.player(p));
            }
        }
    }

    private void putRobot(ByteBuffer b, RobotInfo r) {
        b.put((byte) r.penalty());
        b.put((byte) r.secsTillUnpenalised());
        if (sixByteRobotInfo) {
            b.put((byte) r.warnings());
        }
        b.put((byte) r.yellowCards());
        b.put((byte) r.redCards());
        if (sixByteRobotInfo) {
            b.put((byte) (r.goalkeeper() ? 1 : 0));
        }
    }

    @Override
    Decoded<GameControlData> decodeBody(ByteBuffer b) {
        int packetNumber = WireChecks.u8(b);
        int playersPerTeam = WireChecks.u8(b);
        int gameType = WireChecks.u8(b);
        int state = WireChecks.u8(b);
        boolean firstHalf = WireChecks.u8(b) != 0;
        int kickOff = WireChecks.u8(b);
        if (kickOff == 0x80 || kickOff == 255) {
            kickOff = GameControlData.DROP_BALL;
        }
        int secondaryState = WireChecks.u8(b);
        int setPlayTeam = WireChecks.u8(b);
        int setPlayMode = WireChecks.u8(b);
        b.position(b.position() + 2);
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
            int coachSequence = WireChecks.u8(b);
            b.position(b.position() + COACH_MESSAGE_SIZE);
            RobotInfo coach = getRobot(b);
            List<RobotInfo> players = new ArrayList<>(MAX_PLAYERS);
            for (int p = 0; p < MAX_PLAYERS; p++) {
                players.add(getRobot(b));
            }
            teams.add(new TeamInfo(number, colour, 0, score, penaltyShot, singleShots, coachSequence, 0, coach,
                    players));
        }
        return Decoded.ok(new GameControlData(packetNumber, playersPerTeam, gameType, 0, state, firstHalf, kickOff,
                secondaryState, setPlayTeam, setPlayMode, dropInTeam, dropInTime, secsRemaining, secondaryTime,
                teams));
    }

    private RobotInfo getRobot(ByteBuffer b) {
        if (!sixByteRobotInfo) {
            int penalty = WireChecks.u8(b);
            int secs = WireChecks.u8(b);
            return new RobotInfo(penalty, secs, 0, WireChecks.u8(b), WireChecks.u8(b), false);
        }
        return new RobotInfo(WireChecks.u8(b), WireChecks.u8(b), WireChecks.u8(b), WireChecks.u8(b),
                WireChecks.u8(b), WireChecks.u8(b) != 0);
    }
}
