package touchline.game;

/**
 * Starts the penalty shoot-out, one rule for every league: legal once the second half (HSL: or
 * extra time) has finished level and no shoot-out runs; {@code team} shoots first, or with
 * {@link #GAME_KICK_OFF} the team that kicked off the game (HL's rule; the official HSL
 * GameController names the home team, which did). What a shoot-out is in the league (HL: secondary
 * state PENALTYSHOOT, each kick SET → PLAYING → goal or FINISHED; HSL: every player a substitute
 * until each team selects its shooter, 3 shots each and up to 3 more) is the league's
 * {@link RefereeState#beginShootout}.
 */
public record StartPenaltyShootout(int team) implements RefereeAction {

    /** {@link #team} for the team that kicked off the game. */
    public static final int GAME_KICK_OFF = 0;

    /** The team that kicked off the game shoots first (the HL GameController's only way). */
    public StartPenaltyShootout() {
        this(GAME_KICK_OFF);
    }

    @Override
    public boolean isLegal(RefereeState s) {
        return (team == GAME_KICK_OFF || s.hasTeam(team)) && s.finished() && !s.firstHalf() && !s.inShootout()
                && s.goalDifference() == 0;
    }

    @Override
    public void apply(RefereeState s, long nowMs) {
        s.beginShootout(team == GAME_KICK_OFF ? s.gameKickOffTeam() : team, nowMs);
    }

    /** {@code penaltyshootout} (HL), {@code penalty shoot-out, 5 first} (HSL), as each league's undo list has it. */
    @Override
    public String describe() {
        return team == GAME_KICK_OFF ? "penaltyshootout" : "penalty shoot-out, " + team + " first";
    }
}
