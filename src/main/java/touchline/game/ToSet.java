package touchline.game;

/**
 * READY → SET: robots stand still for the kick-off. In a penalty shoot-out SET starts the next
 * kick (from INITIAL or after the previous kick's FINISHED): the teams take turns and the
 * kicking team's shot counter goes up.
 */
public record ToSet() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        if (s.isPenaltyShootout()) {
            TeamState next = s.state == PlayState.FINISHED ? s.otherTeam(s.kickOffTeam) : s.team(s.kickOffTeam);
            return (s.state == PlayState.INITIAL || s.state == PlayState.FINISHED)
                    && next.penaltyShot < LeagueParams.MAX_PENALTY_SHOTS;
        }
        return s.state == PlayState.READY;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        if (s.isPenaltyShootout()) {
            if (s.state == PlayState.FINISHED) {
                s.kickOffTeam = s.otherTeam(s.kickOffTeam).number;
            }
            s.team(s.kickOffTeam).penaltyShot++;
        }
        s.enter(PlayState.SET, nowMs);
    }

    @Override
    public String describe() {
        return "set";
    }
}
