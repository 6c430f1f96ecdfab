package touchline.game.hsl;

/**
 * After a drawn second half: extra time, two halves of the rules' length (300 s) in the
 * sides and with the kick-off of the first half. Penalties are lifted except send-offs and
 * substitutes; 7.x gives each team 6000 more messages (6.0.1 none).
 */
public record StartExtraTime() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.phase == HslPhase.NORMAL && !s.firstHalf && s.state == HslPlayState.FINISHED
                && s.rules.extraHalfMs() > 0;
    }

    @Override
    public void apply(HslState s) {
        for (HslTeam t : s.teams) {
            for (HslPlayer p : t.players) {
                if (p.isPenalised() && !p.permanent()) {
                    p.unpenalise();
                }
            }
            if (!t.illegalCommunication) {
                t.addBudget(s.rules.messagesExtraTime());
            }
        }
        if (s.teams[0].number != s.firstKickOffTeam) {
            s.teams = new HslTeam[]{s.teams[1], s.teams[0]}; // back to the sides of the first half
        }
        s.phase = HslPhase.EXTRA_TIME;
        s.firstHalf = true;
        s.state = HslPlayState.INITIAL;
        s.kickingTeam = s.firstKickOffTeam;
        s.clockMs = s.rules.extraHalfMs();
        s.addedMs = 0;
        s.halfKickedOff = false;
        s.stoppageClockMs = -1;
        s.switchHalfMs = -1;
        s.startSecondary(SecondaryTimer.NONE, 0);
    }

    @Override
    public String describe() {
        return "extra time";
    }
}
