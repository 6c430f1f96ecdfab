package touchline.game.hsl;

/**
 * A team timeout ({@code team} > 0, outside PLAYING, while it has one left) or a referee
 * timeout ({@code team} 0, also during play). Time spent in READY/SET since the last stoppage
 * is given back; after a team timeout the other team kicks off, after a referee timeout during
 * play the ball is dropped.
 */
public record Timeout(int team) implements HslAction {

    public static final int REFEREE = 0;

    @Override
    public boolean isLegal(HslState s) {
        if (s.phase == HslPhase.PENALTY_SHOOT_OUT || s.state == HslPlayState.FINISHED
                || s.state == HslPlayState.TIMEOUT) {
            return false;
        }
        if (team == REFEREE) {
            return true;
        }
        HslTeam t = s.team(team);
        return t != null && t.timeoutsLeft > 0 && s.state != HslPlayState.PLAYING;
    }

    @Override
    public void apply(HslState s) {
        if ((s.state == HslPlayState.READY || s.state == HslPlayState.SET) && s.stoppageClockMs >= 0) {
            s.clockMs = s.stoppageClockMs;
        }
        if (team == REFEREE) {
            if (s.state == HslPlayState.PLAYING) {
                s.kickingTeam = HslState.NO_TEAM;
            }
            s.startSecondary(SecondaryTimer.TIMEOUT, s.rules.refereeTimeoutMs());
        } else {
            s.team(team).timeoutsLeft--;
            s.kickingTeam = s.otherTeam(team).number;
            s.startSecondary(SecondaryTimer.TIMEOUT, s.rules.timeoutMs());
        }
        s.state = HslPlayState.TIMEOUT;
        s.setPlay = null;
        s.stopped = false;
    }

    @Override
    public String describe() {
        return team == REFEREE ? "referee timeout" : "timeout " + team;
    }
}
