package touchline.game;

/**
 * Swaps a robot on the field ({@code out}) for a substitute ({@code in}): the substitute takes
 * over the outgoing robot's penalty (and its remaining time) and goalkeeper role; the outgoing
 * robot becomes a substitute.
 */
public record Substitute(int team, int out, int in) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        TeamState t = s.team(team);
        return t != null && TeamState.validPlayer(out) && TeamState.validPlayer(in) && out != in
                && t.player(out).penalty != Penalty.SUBSTITUTE && t.player(in).penalty == Penalty.SUBSTITUTE;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        PlayerState leaving = s.team(team).player(out);
        PlayerState entering = s.team(team).player(in);
        entering.penalty = leaving.penalty;
        entering.penaltySinceMs = leaving.penaltySinceMs;
        entering.penaltySeconds = leaving.penaltySeconds;
        entering.goalkeeper = leaving.goalkeeper;
        leaving.penalty = Penalty.SUBSTITUTE;
        leaving.penaltySeconds = 0;
        leaving.goalkeeper = false;
    }

    @Override
    public String describe() {
        return "substitute " + team + " " + out + " " + in;
    }
}
