package touchline.game;

/**
 * A team timeout, taken while play is stopped (INITIAL, READY or SET): INITIAL with secondary
 * state TIMEOUT and the timeout countdown; {@link ToReady} ends it.
 */
public record Timeout(int team) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        TeamState t = s.team(team);
        return t != null && t.timeoutsTaken < s.params.timeoutsPerTeam()
                && (s.state == PlayState.INITIAL || s.state == PlayState.READY || s.state == PlayState.SET)
                && s.secondary == SecondaryState.NORMAL;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.team(team).timeoutsTaken++;
        s.secondary = SecondaryState.TIMEOUT;
        s.timeoutTeam = team;
        s.enter(PlayState.INITIAL, nowMs);
    }

    @Override
    public String describe() {
        return "timeout " + team;
    }
}
