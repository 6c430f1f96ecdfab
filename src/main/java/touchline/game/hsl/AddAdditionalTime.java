package touchline.game.hsl;

/**
 * One minute of additional time (6.0.1: "extra minute"), outside PLAYING once more than a
 * minute of the half was played: the clock gets 60 s and each team's message budget its share
 * (not a team that communicated illegally).
 */
public record AddAdditionalTime() implements HslAction {

    static final long MINUTE_MS = 60_000;

    @Override
    public boolean isLegal(HslState s) {
        return s.phase != HslPhase.PENALTY_SHOOT_OUT && s.state != HslPlayState.PLAYING
                && s.state != HslPlayState.FINISHED && s.playedMs() > MINUTE_MS;
    }

    @Override
    public void apply(HslState s) {
        s.clockMs += MINUTE_MS;
        s.addedMs += MINUTE_MS;
        if (s.stoppageClockMs >= 0) {
            s.stoppageClockMs += MINUTE_MS;
        }
        for (HslTeam t : s.teams) {
            if (!t.illegalCommunication) {
                t.addBudget(s.rules.messagesPerAddedMinute());
            }
        }
    }

    @Override
    public String describe() {
        return "additional minute";
    }
}
