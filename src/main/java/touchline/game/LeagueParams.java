package touchline.game;

/**
 * The rule parameters the game logic needs, all in seconds. The defaults are those of the
 * official HL GameController's "HL Simulation KidSize" league, which the golden datagrams were
 * captured with.
 *
 * @param playersPerTeam      robots on the field per team (the rest start as substitutes)
 * @param halfSeconds         length of a half
 * @param readySeconds        READY countdown
 * @param kickOffBlockSeconds ball-free countdown after a kick-off
 * @param setPlayPrepareSeconds countdown while robots position for a set play
 * @param afterSetPlayBlockSeconds ball-free countdown after a set play is executed
 * @param penaltySeconds      length of a timed penalty
 * @param halfTimePauseSeconds half-time break (the second-half INITIAL counts it down, then below zero)
 * @param timeoutSeconds      length of a team timeout
 * @param timeoutsPerTeam     timeouts a team may take per game
 * @param gameType            byte 8 of the HL packet (0 round robin, 1 playoff)
 * @param penaltyShotSeconds  time for one kick of a penalty shoot-out
 */
public record LeagueParams(int playersPerTeam, int halfSeconds, int readySeconds, int kickOffBlockSeconds,
                           int setPlayPrepareSeconds, int afterSetPlayBlockSeconds, int penaltySeconds,
                           int halfTimePauseSeconds, int timeoutSeconds, int timeoutsPerTeam, int gameType,
                           int penaltyShotSeconds) {

    public static final int MAX_PLAYERS = 11;

    /** Penalty shots counted in singleShots (a u16 bit mask). */
    public static final int MAX_PENALTY_SHOTS = 16;

    /** The same rules with other team size and half length (the CLI's options). */
    public LeagueParams withTeamSizeAndHalf(int players, int half) {
        return new LeagueParams(players, half, readySeconds, kickOffBlockSeconds, setPlayPrepareSeconds,
                afterSetPlayBlockSeconds, penaltySeconds, halfTimePauseSeconds, timeoutSeconds, timeoutsPerTeam,
                gameType, penaltyShotSeconds);
    }

    public LeagueParams {
        if (playersPerTeam < 1 || playersPerTeam > MAX_PLAYERS) {
            throw new IllegalArgumentException("playersPerTeam must be 1.." + MAX_PLAYERS);
        }
    }

    /** "HL Simulation KidSize" of the Java HL GameController v2024.1 (the golden capture). */
    public static LeagueParams hlSimulationKidSize() {
        return new LeagueParams(4, 600, 45, 10, 15, 10, 30, 0, 120, 1, 0, 60);
    }
}
