package touchline.game.hsl;

/**
 * A team message heard on the network (UDP 10000 + team number). In READY, SET and PLAYING
 * (not in a shoot-out) it costs one message of the team's budget; one longer than the limit,
 * or one when the budget is spent, marks the team as communicating illegally: its score
 * becomes 0 and later goals do not count.
 */
public record TeamMessage(int team, int bytes) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.team(team) != null;
    }

    @Override
    public void apply(HslState s) {
        if (!s.state.onField() || s.phase == HslPhase.PENALTY_SHOOT_OUT) {
            return;
        }
        HslTeam t = s.team(team);
        if (bytes > s.rules.maxMessageBytes() || t.messageBudget == 0) {
            t.illegalCommunication = true;
            t.score = 0;
        } else {
            t.messageBudget--;
        }
    }

    @Override
    public String describe() {
        return "team message " + team + " (" + bytes + " bytes)";
    }

    @Override
    public boolean undoable() {
        return false;
    }
}
