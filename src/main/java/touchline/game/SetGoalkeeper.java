package touchline.game;

/** Makes a robot its team's goalkeeper (the previous goalkeeper becomes a field player). */
public record SetGoalkeeper(int team, int player) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        TeamState t = s.team(team);
        return t != null && TeamState.validPlayer(player) && !t.player(player).goalkeeper
                && t.player(player).penalty != Penalty.SUBSTITUTE;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        for (PlayerState p : s.team(team).players) {
            p.goalkeeper = false;
        }
        s.team(team).player(player).goalkeeper = true;
    }

    @Override
    public String describe() {
        return "goalkeeper " + team + " " + player;
    }
}
