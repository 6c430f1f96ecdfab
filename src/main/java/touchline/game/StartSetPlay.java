package touchline.game;

/**
 * Starts a set play (free kick, penalty kick, corner, goal kick, throw-in) for {@code team}
 * during PLAYING: the half clock stops until it is executed or aborted, robots stand still
 * (sub-mode 0) until the referee lets them position ({@link SetPlayStep}).
 */
public record StartSetPlay(int team, SecondaryState kind) implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return kind.isSetPlay() && s.state == PlayState.PLAYING && s.secondary == SecondaryState.NORMAL
                && s.team(team) != null;
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.secondary = kind;
        s.setPlayTeam = team;
        s.setPlayMode = 0;
        s.setPlayModeSinceMs = nowMs;
        s.block(0, nowMs);
    }

    @Override
    public String describe() {
        return kind.name().toLowerCase(java.util.Locale.ROOT) + " " + team;
    }
}
