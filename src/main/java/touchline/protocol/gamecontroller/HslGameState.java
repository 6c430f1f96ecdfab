package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;

/**
 * The layout versions 19 and 20 of the Humanoid Soccer League share (official HSL
 * GameController, {@code game_controller_msgs/headers/RoboCupGameControlData.h}): u8 version,
 * competitionType and {@code stopped} at offsets 7 and 8 (where SPL v18 had competitionPhase
 * and competitionType), game phase and set play side by side, one kicking team (255 = none),
 * 10-byte team header with colours, goalkeeper number and message budget, 20 players. The
 * versions differ only in the RobotInfo (v19 has a warnings byte) and the penalty numbers.
 * Values outside the header's constants are rejected, so whatever decodes encodes back to
 * the same bytes.
 */
abstract sealed class HslGameState extends FixedSizeFormat permits HslGameState19, HslGameState20 {

    static final int MAX_PLAYERS = 20;
    static final int KICKING_TEAM_NONE = 255;
    static final int TEAM_HEADER_SIZE = TeamHeader.SIZE;
    static final int FIXED_PART_SIZE = 18;
    private static final int MAX_GAME_PHASE = 3;
    private static final int MAX_STATE = GameControlData.STATE_FINISHED;
    private static final int MAX_COMPETITION_TYPE = 2;

    private final int version;
    private final boolean warningsByte;

    HslGameState(String kind, byte[] magic, int version, boolean warningsByte) {
        super(kind, magic, version, 1, FIXED_PART_SIZE + 2 * teamSize(warningsByte));
        this.version = version;
        this.warningsByte = warningsByte;
    }

    static int teamSize(boolean warningsByte) {
        return TEAM_HEADER_SIZE + MAX_PLAYERS * (warningsByte ? 4 : 3);
    }

    @Override
    final void encodeBody(GameControlData d, ByteBuffer b) {
        b.put((byte) d.packetNumber());
        b.put((byte) d.playersPerTeam());
        b.put((byte) d.competitionType());
        b.put((byte) (d.stopped() ? 1 : 0));
        b.put((byte) d.gamePhase());
        // HSL has no STANDBY: the robots wait as in INITIAL
        b.put((byte) (d.state() > MAX_STATE ? GameControlData.STATE_INITIAL : d.state()));
        HslSetPlay setPlay = HslSetPlay.ofSecondaryState(d.secondaryState());
        b.put((byte) setPlay.wire());
        b.put((byte) (d.firstHalf() ? 1 : 0));
        int kicking = setPlay != HslSetPlay.NONE ? d.setPlayTeam() : d.kickOffTeam();
        b.put((byte) (kicking == GameControlData.DROP_BALL ? KICKING_TEAM_NONE : kicking));
        b.putShort((short) d.secsRemaining());
        b.putShort((short) d.secondaryTime());
        for (TeamInfo t : d.teams()) {
            TeamHeader.write(t, b, MAX_PLAYERS);
            for (int p = 1; p <= MAX_PLAYERS; p++) {
                RobotInfo r = t.player(p);
                b.put((byte) HslPenalty.ofNeutral(r.penalty()).wire(version));
                b.put((byte) Math.max(0, Math.min(255, r.secsTillUnpenalised())));
                if (warningsByte) {
                    b.put((byte) r.warnings());
                }
                b.put((byte) r.cautions());
            }
        }
    }

    @Override
    final Decoded<GameControlData> decodeBody(ByteBuffer b) {
        int packetNumber = WireChecks.u8(b);
        int playersPerTeam = WireChecks.u8(b);
        int competitionType = WireChecks.u8(b);
        int stopped = WireChecks.u8(b);
        int gamePhase = WireChecks.u8(b);
        int state = WireChecks.u8(b);
        int setPlayCode = WireChecks.u8(b);
        int firstHalf = WireChecks.u8(b);
        int kicking = WireChecks.u8(b);
        int secsRemaining = b.getShort();
        int secondaryTime = b.getShort();
        HslSetPlay setPlay = HslSetPlay.ofWire(setPlayCode);
        String bad = playersPerTeam > MAX_PLAYERS ? "playersPerTeam " + playersPerTeam + " > " + MAX_PLAYERS
                : competitionType > MAX_COMPETITION_TYPE ? "competitionType " + competitionType + " not in 0..2"
                : stopped > 1 ? "stopped " + stopped + " not 0/1"
                : gamePhase > MAX_GAME_PHASE ? "gamePhase " + gamePhase + " not in 0..3"
                : state > MAX_STATE ? "state " + state + " not in 0..4"
                : setPlay == null ? "setPlay " + setPlayCode + " not in 0..6"
                : firstHalf > 1 ? "firstHalf " + firstHalf + " not 0/1"
                : null;
        if (bad != null) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, bad);
        }
        int kickingTeam = kicking == KICKING_TEAM_NONE ? GameControlData.DROP_BALL : kicking;
        List<TeamInfo> teams = new ArrayList<>(2);
        for (int t = 0; t < 2; t++) {
            Decoded<TeamInfo> team = decodeTeam(b, t);
            if (!team.isOk()) {
                return team.asRejected();
            }
            teams.add(team.value());
        }
        // the neutral form keeps one secondary state: a running set play, else the game phase
        boolean setPlayRuns = setPlay != HslSetPlay.NONE;
        return Decoded.ok(new GameControlData(packetNumber, playersPerTeam, 0, competitionType, state, firstHalf == 1,
                kickingTeam, setPlayRuns ? setPlay.secondaryState() : gamePhase, setPlayRuns ? kickingTeam : 0, 0, 0, 0,
                secsRemaining, secondaryTime, teams, gamePhase, stopped == 1));
    }

    private Decoded<TeamInfo> decodeTeam(ByteBuffer b, int index) {
        TeamHeader.Fields h = TeamHeader.read(b);
        String team = "teams[" + index + "] ";
        if (TeamColour.ofWire(h.colour()) == null || TeamColour.ofWire(h.goalkeeperColour()) == null) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, team + "colour " + h.colour() + "/"
                    + h.goalkeeperColour() + " not in 0..9");
        }
        if (h.goalkeeper() > MAX_PLAYERS) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, team + "goalkeeper " + h.goalkeeper() + " > "
                    + MAX_PLAYERS);
        }
        List<RobotInfo> players = new ArrayList<>(MAX_PLAYERS);
        for (int p = 1; p <= MAX_PLAYERS; p++) {
            int code = WireChecks.u8(b);
            int secs = WireChecks.u8(b);
            int warnings = warningsByte ? WireChecks.u8(b) : 0;
            int cautions = WireChecks.u8(b);
            HslPenalty penalty = HslPenalty.ofWire(version, code);
            if (penalty == null) {
                return Decoded.rejected(DecodeFailure.INVALID_FIELD, team + "player " + p + ": penalty " + code
                        + " unknown in version " + version);
            }
            players.add(new RobotInfo(penalty.neutral(), secs, warnings, cautions, 0, p == h.goalkeeper()));
        }
        return Decoded.ok(h.team(players));
    }
}
