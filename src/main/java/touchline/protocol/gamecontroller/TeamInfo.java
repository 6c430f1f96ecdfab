package touchline.protocol.gamecontroller;

import java.util.List;

/**
 * One team's block of a game-state packet, format-neutral. Fields a format does not carry
 * are written as zero and read back as zero (e.g. {@code messageBudget} outside SPL and HSL).
 *
 * @param teamNumber       the team's number
 * @param colour           field player colour (0 blue/cyan, 1 red/magenta, 2 yellow ... 9 gray)
 * @param goalkeeperColour SPL / HSL goalkeeper colour
 * @param score            goals scored
 * @param penaltyShot      penalty shot counter (SPL v18 outside a shoot-out: fallback flag)
 * @param singleShots      bit mask of successful penalty shots
 * @param coachSequence    HL coach message sequence number
 * @param messageBudget    SPL / HSL team messages the team may still send in this game
 * @param coach            the coach's robot info (HL v12, v8)
 * @param players          the players, index 0 = player 1
 */
public record TeamInfo(int teamNumber, int colour, int goalkeeperColour, int score, int penaltyShot, int singleShots,
                       int coachSequence, int messageBudget, RobotInfo coach, List<RobotInfo> players) {

    public TeamInfo {
        players = List.copyOf(players);
    }

    /** Player {@code number} (1-based), or an empty entry when the team has fewer. */
    public RobotInfo player(int number) {
        return number >= 1 && number <= players.size() ? players.get(number - 1) : RobotInfo.EMPTY;
    }
}
