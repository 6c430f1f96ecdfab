package touchline.game;

/** Penalises an unpenalised robot; timed penalties end by themselves after the league's time. */
public record Penalize(int team, int player, Penalty penalty) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        TeamState t = s.team(team);
        return t != null && TeamState.validPlayer(player) && s.state != PlayState.FINISHED
                && penalty != Penalty.NONE && penalty != Penalty.SUBSTITUTE
                && t.player(player).penalty == Penalty.NONE;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.team(team).player(player).penalise(penalty, nowMs, s.params.penaltySeconds());
    }

    @Override
    public String describe() {
        return "penalty " + team + " " + player + " " + penalty.name().toLowerCase(java.util.Locale.ROOT);
    }
}
