package touchline.game.hsl;

/**
 * After a drawn second half (or extra time): the penalty shoot-out, {@code team} shooting first
 * (the official GameController: always the home team). Every player becomes a substitute
 * until its team selects one ({@link SelectShooter}); each shot is INITIAL → SET
 * ({@link PenaltyShot}) → PLAYING (the whistle, with robots seeing SET for the
 * usual delay) → FINISHED (a goal, {@link FinishPenaltyShot}, or its 60 s run out); the teams
 * alternate, 3 shots each and up to 3 more in sudden death. Team messages do not count.
 */
public record StartPenaltyShootout(int team) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.team(team) != null && s.phase != HslPhase.PENALTY_SHOOT_OUT && s.state == HslPlayState.FINISHED
                && !s.firstHalf && s.teams[0].score == s.teams[1].score;
    }

    @Override
    public void apply(HslState s) {
        s.phase = HslPhase.PENALTY_SHOOT_OUT;
        s.state = HslPlayState.INITIAL;
        s.kickingTeam = team;
        s.clockMs = s.rules.penaltyShotMs();
        s.switchHalfMs = -1;
        s.startSecondary(SecondaryTimer.NONE, 0);
        // as the official GameController: everybody off, each team then picks its player (SelectShooter)
        for (HslTeam t : s.teams) {
            t.goalkeeper = 0;
            t.penaltyShot = 0;
            t.singleShots = 0;
            for (HslPlayer p : t.players) {
                p.penalise(touchline.protocol.gamecontroller.HslPenalty.SUBSTITUTE, 0, false);
            }
        }
    }

    @Override
    public String describe() {
        return "penalty shoot-out, " + team + " first";
    }
}
