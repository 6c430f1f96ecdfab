package touchline.game.hsl;

/**
 * A goal for {@code team} (not counted while the team is marked for illegal communication):
 * READY with the other team's kick-off, or the end of the game by the mercy rule; in a
 * penalty shoot-out the shot is scored in singleShots and over.
 */
public record Goal(int team) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        if (s.phase == HslPhase.PENALTY_SHOOT_OUT) {
            return s.state == HslPlayState.PLAYING && s.kickingTeam == team;
        }
        return s.team(team) != null && s.state == HslPlayState.PLAYING;
    }

    @Override
    public void apply(HslState s) {
        HslTeam scorer = s.team(team);
        HslTeam other = s.otherTeam(team);
        if (!scorer.illegalCommunication) {
            scorer.score++;
        }
        if (s.phase == HslPhase.PENALTY_SHOOT_OUT) {
            scorer.singleShots |= 1 << (scorer.penaltyShot - 1);
            s.endShot();
            return;
        }
        if (Math.abs(scorer.score - other.score) >= s.rules.mercyGoals()) {
            s.firstHalf = false; // the game is over: no half-time break, no second half
            s.finish();
            return;
        }
        s.beginStoppage();
        s.enterReady(SetPlay.KICK_OFF, other.number);
    }

    @Override
    public String describe() {
        return "goal " + team;
    }
}
