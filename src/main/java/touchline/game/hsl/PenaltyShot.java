package touchline.game.hsl;

/** The next shoot-out shot of the team whose turn it is: SET with 60 s on the clock. */
public record PenaltyShot() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        if (s.phase != HslPhase.PENALTY_SHOOT_OUT
                || (s.state != HslPlayState.INITIAL && s.state != HslPlayState.FINISHED)) {
            return false;
        }
        HslTeam shooter = s.team(s.kickingTeam);
        return shooter != null && shooter.penaltyShot < s.rules.penaltyShots() + s.rules.suddenDeathShots();
    }

    @Override
    public void apply(HslState s) {
        s.team(s.kickingTeam).penaltyShot++;
        s.state = HslPlayState.SET;
        s.clockMs = s.rules.penaltyShotMs();
    }

    @Override
    public String describe() {
        return "penalty shot";
    }
}
