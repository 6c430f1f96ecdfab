package touchline.game;

/**
 * A goal for {@code team}: score +1, back to READY, the other team kicks off. In a penalty
 * shoot-out only the kicking team can score; the kick is recorded in singleShots and ends.
 */
public record Goal(int team) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.PLAYING && s.team(team) != null
                && (!s.isPenaltyShootout() || s.kickOffTeam == team);
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.team(team).score++;
        if (s.isPenaltyShootout()) {
            TeamState t = s.team(team);
            t.singleShots |= 1 << (t.penaltyShot - 1);
            s.enter(PlayState.FINISHED, nowMs);
            return;
        }
        s.kickOffTeam = s.otherTeam(team).number;
        s.endSetPlay();
        s.block(0, nowMs);
        s.enter(PlayState.READY, nowMs);
    }

    @Override
    public String describe() {
        return "goal " + team;
    }
}
