package touchline.game.hsl;

/** Field names of a v19/v20 datagram offset, for failure messages of the golden tests. */
final class HslFields {

    private static final String[] FIXED = {"header", "header", "header", "header", "version", "packetNumber",
            "playersPerTeam", "competitionType", "stopped", "gamePhase", "state", "setPlay", "firstHalf",
            "kickingTeam", "secsRemaining", "secsRemaining", "secondaryTime", "secondaryTime"};
    private static final String[] TEAM = {"teamNumber", "fieldPlayerColour", "goalkeeperColour", "goalkeeper",
            "score", "penaltyShot", "singleShots", "singleShots", "messageBudget", "messageBudget"};

    private HslFields() {
    }

    static String name(int offset, int version) {
        if (offset < FIXED.length) {
            return FIXED[offset];
        }
        int robot = version == 19 ? 4 : 3;
        int teamSize = 10 + 20 * robot;
        int team = (offset - 18) / teamSize;
        int in = (offset - 18) % teamSize;
        if (in < TEAM.length) {
            return "teams[" + team + "]." + TEAM[in];
        }
        int player = (in - 10) / robot + 1;
        int field = (in - 10) % robot;
        String[] names = version == 19 ? new String[]{"penalty", "secsTillUnpenalised", "warnings", "cautions"}
                : new String[]{"penalty", "secsTillUnpenalised", "cautions"};
        return "teams[" + team + "].player" + player + "." + names[field];
    }
}
