package touchline.game.hsl;

import touchline.protocol.gamecontroller.HslPenalty;

/**
 * In a penalty shoot-out, the team's one player on the field (the shooter, or the defending
 * goalkeeper); every other player of the team becomes a substitute. {@code goalkeeper} says
 * whether the player wears the goalkeeper jersey (the team's goalkeeper number, else 0).
 */
public record SelectShooter(int team, int player, boolean goalkeeper) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        HslTeam t = s.team(team);
        return t != null && s.phase == HslPhase.PENALTY_SHOOT_OUT && HslTeam.validPlayer(player)
                && t.player(player).penalty != HslPenalty.SENT_OFF
                && (s.state == HslPlayState.INITIAL || s.state == HslPlayState.FINISHED
                || s.state == HslPlayState.SET);
    }

    @Override
    public void apply(HslState s) {
        HslTeam t = s.team(team);
        for (int n = 1; n <= HslRules.MAX_PLAYERS; n++) {
            HslPlayer p = t.player(n);
            if (p.penalty != HslPenalty.SENT_OFF) {
                if (n == player) {
                    p.unpenalise();
                } else {
                    p.penalise(HslPenalty.SUBSTITUTE, 0, false);
                }
            }
        }
        t.goalkeeper = goalkeeper ? player : 0;
    }

    /** Players of the team not out as substitutes or sent off. */
    static long onField(HslTeam t) {
        long n = 0;
        for (HslPlayer p : t.players) {
            if (!p.permanent()) {
                n++;
            }
        }
        return n;
    }

    @Override
    public String describe() {
        return "shooter " + team + " " + player + (goalkeeper ? " goalkeeper" : "");
    }
}
