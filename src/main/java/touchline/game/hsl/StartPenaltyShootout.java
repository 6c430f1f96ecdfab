package touchline.game.hsl;

/**
 * After a drawn second half: the penalty shoot-out, {@code team} shooting first. Each shot is
 * INITIAL → SET ({@link PenaltyShot}) → PLAYING (the whistle, with robots seeing SET for the
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
        for (HslTeam t : s.teams) {
            for (HslPlayer p : t.players) {
                if (p.isPenalised() && !p.permanent()) {
                    p.unpenalise();
                }
            }
        }
    }

    @Override
    public String describe() {
        return "penalty shoot-out, " + team + " first";
    }
}
