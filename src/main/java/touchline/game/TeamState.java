package touchline.game;

/**
 * One team's referee record: number, colour, score, penalty-shot counters, timeouts taken and
 * its {@value LeagueParams#MAX_PLAYERS} player slots (player n at index n-1). Mutable; owned by
 * a {@link GameState}.
 */
public final class TeamState implements RefereeState.Team {

    final int number;
    final int colour;
    int score;
    int penaltyShot;
    int singleShots;
    int timeoutsTaken;
    final PlayerState[] players = new PlayerState[LeagueParams.MAX_PLAYERS];

    TeamState(int number, int colour, int playersPerTeam) {
        this.number = number;
        this.colour = colour;
        for (int i = 0; i < players.length; i++) {
            players[i] = new PlayerState();
            if (i >= playersPerTeam) {
                players[i].penalty = Penalty.SUBSTITUTE;
            }
        }
        players[0].goalkeeper = true;
    }

    private TeamState(TeamState o) {
        number = o.number;
        colour = o.colour;
        score = o.score;
        penaltyShot = o.penaltyShot;
        singleShots = o.singleShots;
        timeoutsTaken = o.timeoutsTaken;
        for (int i = 0; i < players.length; i++) {
            players[i] = o.players[i].copy();
        }
    }

    TeamState copy() {
        return new TeamState(this);
    }

    public int number() {
        return number;
    }

    public int colour() {
        return colour;
    }

    public int score() {
        return score;
    }

    public int timeoutsTaken() {
        return timeoutsTaken;
    }

    /** Player {@code n} (1-based). */
    public PlayerState player(int n) {
        return players[n - 1];
    }

    static boolean validPlayer(int n) {
        return n >= 1 && n <= LeagueParams.MAX_PLAYERS;
    }
}
