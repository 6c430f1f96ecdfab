package touchline.game;

/**
 * Starts a penalty shoot-out after a drawn second half: INITIAL with secondary state
 * PENALTYSHOOT, the team that kicked off the game shoots first, shot counters start at zero.
 * Each kick is then SET → PLAYING (kick countdown) → goal or FINISHED.
 */
public record StartPenaltyShootout() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.FINISHED && !s.firstHalf && !s.isPenaltyShootout()
                && s.teams[0].score == s.teams[1].score;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.secondary = SecondaryState.PENALTYSHOOT;
        s.kickOffTeam = s.firstHalfKickOffTeam;
        for (TeamState t : s.teams) {
            t.penaltyShot = 0;
            t.singleShots = 0;
        }
        s.restartClock(nowMs);
    }

    @Override
    public String describe() {
        return "penaltyshootout";
    }
}
