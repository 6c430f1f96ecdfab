package touchline.game;

/** A goal for {@code team}: score +1, back to READY, the other team kicks off. */
public record Goal(int team) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.PLAYING && s.team(team) != null;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.team(team).score++;
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
