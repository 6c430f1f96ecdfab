package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.util.List;

/**
 * The 10-byte team header SPL v18 and HSL v19/v20 share: teamNumber, fieldPlayerColour,
 * goalkeeperColour, goalkeeper (player number, 0 = none), score, penaltyShot, singleShots
 * (u16), messageBudget (u16).
 */
final class TeamHeader {

    static final int SIZE = 10;

    private TeamHeader() {
    }

    /** The header as read, before the players. */
    record Fields(int number, int colour, int goalkeeperColour, int goalkeeper, int score, int penaltyShot,
                  int singleShots, int messageBudget) {

        TeamInfo team(List<RobotInfo> players) {
            return new TeamInfo(number, colour, goalkeeperColour, score, penaltyShot, singleShots, 0, messageBudget,
                    RobotInfo.EMPTY, players);
        }
    }

    static Fields read(ByteBuffer b) {
        return new Fields(WireChecks.u8(b), WireChecks.u8(b), WireChecks.u8(b), WireChecks.u8(b), WireChecks.u8(b),
                WireChecks.u8(b), WireChecks.u16(b), WireChecks.u16(b));
    }

    static void write(TeamInfo t, ByteBuffer b, int maxPlayers) {
        b.put((byte) t.teamNumber());
        b.put((byte) t.colour());
        b.put((byte) t.goalkeeperColour());
        b.put((byte) goalkeeperNumber(t, maxPlayers));
        b.put((byte) t.score());
        b.put((byte) t.penaltyShot());
        b.putShort((short) t.singleShots());
        b.putShort((short) t.messageBudget());
    }

    /** The number of the first player flagged as goalkeeper, 0 when none is. */
    static int goalkeeperNumber(TeamInfo t, int maxPlayers) {
        for (int p = 1; p <= Math.min(maxPlayers, t.players().size()); p++) {
            if (t.player(p).goalkeeper()) {
                return p;
            }
        }
        return 0;
    }
}
