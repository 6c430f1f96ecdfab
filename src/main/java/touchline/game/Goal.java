package touchline.game;

/**
 * A goal for {@code team}, one rule for every league: legal in PLAYING for a team of the game, in
 * a penalty shoot-out only for the shooter. The score goes up (HSL: not for a team marked for
 * illegal communication); a shoot-out shot is marked in singleShots and over; a goal difference
 * of the league's mercy rule ends the game (HSL: 10; HL, SPL: none); else READY with the other
 * team's kick-off.
 */
public record Goal(int team) implements RefereeAction {
    @Override
    public boolean isLegal(RefereeState s) {
        return s.playing() && s.hasTeam(team) && (!s.inShootout() || s.kickingTeam() == team);
    }

    @Override
    public void apply(RefereeState s, long nowMs) {
        s.countGoal(team);
        if (s.inShootout()) {
            s.shotScored(team, nowMs);
        } else if (s.mercyGoals() > 0 && s.goalDifference() >= s.mercyGoals()) {
            s.endGame(nowMs);
        } else {
            s.readyForKickOff(s.opponent(team), nowMs);
        }
    }

    @Override
    public String describe() {
        return "goal " + team;
    }
}
