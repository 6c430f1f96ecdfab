package touchline.game;

/** A warning, yellow or red card for a robot; counted on the robot, kept over half time. */
public record Card(int team, int player, Kind kind) implements Action {

    /** What the referee shows. */
    public enum Kind { WARNING, YELLOW, RED }

    @Override
    public boolean isLegal(GameState s) {
        return s.team(team) != null && TeamState.validPlayer(player);
    }

    @Override
    public void apply(GameState s, long nowMs) {
        PlayerState p = s.team(team).player(player);
        switch (kind) {
            case WARNING -> p.warnings++;
            case YELLOW -> p.yellowCards++;
            case RED -> p.redCards++;
        }
    }

    @Override
    public String describe() {
        return "card " + team + " " + player + " " + kind.name().toLowerCase(java.util.Locale.ROOT);
    }
}
