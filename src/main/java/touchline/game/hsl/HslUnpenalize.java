package touchline.game.hsl;

/**
 * The operator's button on a penalised robot: the first press starts the penalty timer (the
 * robot is outside), a press after the timer reached 0 lets the robot back in. {@code force}
 * lets it back at once. A sent-off player and a substitute stay out.
 */
public record HslUnpenalize(int team, int player, boolean force) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        HslTeam t = s.team(team);
        if (t == null || !HslTeam.validPlayer(player)) {
            return false;
        }
        HslPlayer p = t.player(player);
        if (!p.isPenalised() || p.permanent()) {
            return false;
        }
        return force || !p.timerStarted || p.penaltyMs <= 0;
    }

    @Override
    public void apply(HslState s) {
        HslPlayer p = s.team(team).player(player);
        if (force || p.timerStarted) {
            p.unpenalise();
        } else {
            p.timerStarted = true;
            p.penaltyMs = p.penaltyDurationMs;
        }
    }

    @Override
    public String describe() {
        return "unpenalize " + team + " " + player + (force ? " force" : "");
    }
}
