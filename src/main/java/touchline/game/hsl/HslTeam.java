package touchline.game.hsl;

import touchline.game.RefereeState;
import touchline.protocol.gamecontroller.TeamColour;

/**
 * One team of an HSL game: number, colours, goalkeeper, score, team-message budget (and
 * whether it communicated illegally, which zeroes and freezes its score), timeouts left,
 * shoot-out shots and its 20 jerseys.
 */
public final class HslTeam implements RefereeState.Team {

    final int number;
    final TeamColour fieldColour;
    final TeamColour goalkeeperColour;
    int goalkeeper = 1;
    int score;
    int penaltyShot;
    int singleShots;
    int messageBudget;
    boolean illegalCommunication;
    int timeoutsLeft;
    /** Earlier incremental penalties of the team (each makes the next one longer). */
    int incrementalPenalties;
    final HslPlayer[] players = new HslPlayer[HslRules.MAX_PLAYERS];

    HslTeam(int number, TeamColour fieldColour, TeamColour goalkeeperColour, HslRules rules) {
        this.number = number;
        this.fieldColour = fieldColour;
        this.goalkeeperColour = goalkeeperColour;
        this.messageBudget = rules.messageBudget();
        this.timeoutsLeft = rules.timeoutsPerTeam();
        for (int i = 0; i < players.length; i++) {
            players[i] = new HslPlayer();
            if (i >= rules.competition().playersPerTeam()) {
                players[i].penalty = touchline.protocol.gamecontroller.HslPenalty.SUBSTITUTE;
            }
        }
    }

    private HslTeam(HslTeam o) {
        number = o.number;
        fieldColour = o.fieldColour;
        goalkeeperColour = o.goalkeeperColour;
        goalkeeper = o.goalkeeper;
        score = o.score;
        penaltyShot = o.penaltyShot;
        singleShots = o.singleShots;
        messageBudget = o.messageBudget;
        illegalCommunication = o.illegalCommunication;
        timeoutsLeft = o.timeoutsLeft;
        incrementalPenalties = o.incrementalPenalties;
        for (int i = 0; i < players.length; i++) {
            players[i] = o.players[i].copy();
        }
    }

    HslTeam copy() {
        return new HslTeam(this);
    }

    public int number() {
        return number;
    }

    public TeamColour fieldColour() {
        return fieldColour;
    }

    public TeamColour goalkeeperColour() {
        return goalkeeperColour;
    }

    public int goalkeeper() {
        return goalkeeper;
    }

    public int score() {
        return score;
    }

    public int messageBudget() {
        return messageBudget;
    }

    public boolean illegalCommunication() {
        return illegalCommunication;
    }

    public int timeoutsLeft() {
        return timeoutsLeft;
    }

    public int penaltyShot() {
        return penaltyShot;
    }

    public int singleShots() {
        return singleShots;
    }

    static boolean validPlayer(int number) {
        return number >= 1 && number <= HslRules.MAX_PLAYERS;
    }

    /** Jersey {@code number} (1..20). */
    public HslPlayer player(int number) {
        return players[number - 1];
    }

    void addBudget(int messages) {
        messageBudget = Math.min(0xFFFF, messageBudget + messages);
    }
}
