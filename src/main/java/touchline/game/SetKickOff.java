package touchline.game;

/** Chooses the team kicking off the game (coin toss), before the first kick-off. */
public record SetKickOff(int team) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.INITIAL && s.firstHalf && !s.halfStarted && s.team(team) != null
                && s.kickOffTeam != team;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.kickOffTeam = team;
        s.firstHalfKickOffTeam = team;
    }

    @Override
    public String describe() {
        return "kickoff " + team;
    }
}
