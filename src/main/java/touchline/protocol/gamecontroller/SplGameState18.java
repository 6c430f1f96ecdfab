package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;

/**
 * SPL RoboCupGameControlData version 18, 118 bytes (GameController3 v3.0.0 … v5.0.0,
 * {@code game_controller_msgs/headers/RoboCupGameControlData.h}). SPL splits the HL
 * secondary state into gamePhase (penalty shoot-out, overtime, timeout) and setPlay, names the
 * kicking team (255 = none) instead of a set-play team, and has 20 two-byte player entries.
 * HL penalties are translated to their nearest SPL code on encode (ball manipulation → illegal
 * ball contact, physical contact → pushing, illegal attack/defence → illegal position,
 * pickup/service → request for pickup); SPL codes are read back unchanged.
 */
public final class SplGameState18 extends FixedSizeFormat {

    public static final int SIZE = 118;
    public static final int VERSION = 18;
    public static final int MAX_PLAYERS = 20;
    public static final int KICKING_TEAM_NONE = 255;
    /** SPL setPlay code for each HL secondary state (0–3 are game phases, not set plays). */
    private static final int[] SET_PLAY_OF_SECONDARY = {0, 0, 0, 0, 2, 2, 5, 3, 1, 4};
    /** HL secondary state for each SPL setPlay code (pushing free kick reads back as direct). */
    private static final int[] SECONDARY_OF_SET_PLAY = {0, 8, 4, 7, 9, 6};

    public SplGameState18() {
        super("gc.spl18", VERSION, 1, SIZE);
    }

    @Override
    void encodeBody(GameControlData d, ByteBuffer b) {
        b.put((byte) d.packetNumber());
        b.put((byte) d.playersPerTeam());
        b.put((byte) d.gameType());
        b.put((byte) d.competitionType());
        int secondary = d.secondaryState();
        b.put((byte) (secondary >= 1 && secondary <= 3 ? secondary : 0));
        b.put((byte) d.state());
        int setPlay = setPlayCode(secondary);
        b.put((byte) setPlay);
        b.put((byte) (d.firstHalf() ? 1 : 0));
        int kicking = setPlay != 0 ? d.setPlayTeam() : d.kickOffTeam();
        b.put((byte) (kicking == GameControlData.DROP_BALL ? KICKING_TEAM_NONE : kicking));
        b.putShort((short) d.secsRemaining());
        b.putShort((short) d.secondaryTime());
        for (TeamInfo t : d.teams()) {
            TeamHeader.write(t, b, MAX_PLAYERS);
            for (int p = 1; p <= MAX_PLAYERS; p++) {
                RobotInfo r = t.player(p);
                b.put((byte) splPenalty(r.penalty()));
                b.put((byte) r.secsTillUnpenalised());
            }
        }
    }

    static int setPlayCode(int secondaryState) {
        return secondaryState >= 0 && secondaryState < SET_PLAY_OF_SECONDARY.length
                ? SET_PLAY_OF_SECONDARY[secondaryState] : 0;
    }

    static int secondaryFromSetPlay(int setPlay) {
        return setPlay >= 0 && setPlay < SECONDARY_OF_SET_PLAY.length ? SECONDARY_OF_SET_PLAY[setPlay] : 0;
    }

    static int splPenalty(int hlPenalty) {
        return switch (hlPenalty) {
            case 30 -> 1;
            case 31 -> 2;
            case 32, 33 -> 5;
            case 34, 35 -> 7;
            default -> hlPenalty;
        };
    }

    @Override
    Decoded<GameControlData> decodeBody(ByteBuffer b) {
        int packetNumber = WireChecks.u8(b);
        int playersPerTeam = WireChecks.u8(b);
        int phase = WireChecks.u8(b);
        int competitionType = WireChecks.u8(b);
        int gamePhase = WireChecks.u8(b);
        int state = WireChecks.u8(b);
        int setPlay = WireChecks.u8(b);
        boolean firstHalf = WireChecks.u8(b) != 0;
        int kicking = WireChecks.u8(b);
        int kickOff = kicking == KICKING_TEAM_NONE ? GameControlData.DROP_BALL : kicking;
        int secsRemaining = b.getShort();
        int secondaryTime = b.getShort();
        // The neutral form has one secondary state: a running set play wins over the game phase.
        int fromSetPlay = secondaryFromSetPlay(setPlay);
        int secondary = fromSetPlay != 0 ? fromSetPlay : gamePhase;
        int setPlayTeam = fromSetPlay != 0 ? kicking : 0;
        List<TeamInfo> teams = new ArrayList<>(2);
        for (int t = 0; t < 2; t++) {
            TeamHeader.Fields header = TeamHeader.read(b);
            List<RobotInfo> players = new ArrayList<>(MAX_PLAYERS);
            for (int p = 1; p <= MAX_PLAYERS; p++) {
                players.add(new RobotInfo(WireChecks.u8(b), WireChecks.u8(b), 0, 0, 0, p == header.goalkeeper()));
            }
            teams.add(header.team(players));
        }
        return Decoded.ok(new GameControlData(packetNumber, playersPerTeam, phase, competitionType, state, firstHalf,
                kickOff, secondary, setPlayTeam, 0, 0, 0, secsRemaining, secondaryTime, teams));
    }
}
