package touchline.game.hsl;

/** Makes {@code player} the team's goalkeeper (0: none), outside PLAYING. */
public record SelectGoalkeeper(int team, int player) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        HslTeam t = s.team(team);
        return t != null && (player == 0 || HslTeam.validPlayer(player)) && s.state != HslPlayState.PLAYING
                && (player == 0 || !t.player(player).permanent());
    }

    @Override
    public void apply(HslState s) {
        s.team(team).goalkeeper = player;
    }

    @Override
    public String describe() {
        return "goalkeeper " + team + " " + player;
    }
}
