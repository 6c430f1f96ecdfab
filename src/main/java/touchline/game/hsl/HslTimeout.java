package touchline.game.hsl;

import touchline.protocol.gamecontroller.HslPenalty;

/**
 * A team timeout ({@code team} > 0; outside PLAYING and the READY/SET of a penalty kick, while
 * it has one left) or a referee timeout ({@code team} 0, also during play), as the official
 * GameController: penalty timers are stopped (the operator starts them again), time spent in
 * READY/SET since the last stoppage is given back, a timeout taken during a timeout (or early
 * in the half-time break) adds to it. After a team timeout the other team kicks off; after a
 * referee timeout the kick-off stands if one was due, else the ball is dropped.
 */
public record HslTimeout(int team) implements HslAction {

    public static final int REFEREE = 0;

    @Override
    public boolean isLegal(HslState s) {
        if (s.phase == HslPhase.PENALTY_SHOOT_OUT || s.state == HslPlayState.FINISHED) {
            return false;
        }
        if (team == REFEREE) {
            return true;
        }
        HslTeam t = s.team(team);
        return t != null && t.timeoutsLeft > 0 && s.state != HslPlayState.PLAYING
                && (s.setPlay == null || s.setPlay == SetPlay.KICK_OFF);
    }

    @Override
    public void apply(HslState s) {
        for (HslTeam t : s.teams) {
            for (HslPlayer p : t.players) {
                if (p.isPenalised() && p.timerStarted && p.penalty != HslPenalty.MOTION_IN_SET) {
                    p.timerStarted = false;
                    p.penaltyMs = p.penaltyDurationMs;
                }
            }
        }
        if ((s.state == HslPlayState.READY || s.state == HslPlayState.SET) && s.stoppageClockMs >= 0) {
            s.clockMs = s.stoppageClockMs;
        }
        s.stoppageClockMs = -1;
        if (team != REFEREE) {
            s.team(team).timeoutsLeft--;
            s.kickingTeam = s.otherTeam(team).number;
        } else if (s.state != HslPlayState.INITIAL && s.state != HslPlayState.TIMEOUT
                && s.setPlay != SetPlay.KICK_OFF) {
            s.kickingTeam = HslState.NO_TEAM;
        }
        long duration = team == REFEREE ? s.rules.refereeTimeoutMs() : s.rules.timeoutMs();
        boolean adds = s.state == HslPlayState.TIMEOUT || (s.state == HslPlayState.INITIAL && !s.firstHalf
                && s.secondary == SecondaryTimer.HALF_TIME_BREAK && s.secondaryMs > 0);
        s.startSecondary(SecondaryTimer.TIMEOUT, adds ? s.secondaryMs + duration : duration);
        s.state = HslPlayState.TIMEOUT;
        s.setPlay = null;
        s.stopped = false;
    }

    @Override
    public String describe() {
        return team == REFEREE ? "referee timeout" : "timeout " + team;
    }
}
