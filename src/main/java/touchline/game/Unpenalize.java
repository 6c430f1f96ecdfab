package touchline.game;

/** Lifts a robot's penalty before its time (substitutes come in with {@link Substitute}). */
public record Unpenalize(int team, int player) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        TeamState t = s.team(team);
        return t != null && TeamState.validPlayer(player) && t.player(player).isPenalised();
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.team(team).player(player).unpenalise();
    }

    @Override
    public String describe() {
        return "unpenalise " + team + " " + player;
    }
}
