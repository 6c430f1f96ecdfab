package touchline.game.hsl;

/**
 * The end of a half: FINISHED. After a first half the half-time break runs, and the second
 * half begins by itself after the rules' time (or by {@link SwitchHalf}).
 */
public record FinishHalf() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.phase != HslPhase.PENALTY_SHOOT_OUT && s.state != HslPlayState.INITIAL
                && s.state != HslPlayState.FINISHED && s.state != HslPlayState.TIMEOUT;
    }

    @Override
    public void apply(HslState s) {
        s.finish();
        if (s.firstHalf) {
            s.startSecondary(SecondaryTimer.HALF_TIME_BREAK, s.rules.halfTimeBreakMs());
            s.switchHalfMs = s.rules.switchHalfAfterMs();
        }
    }

    @Override
    public String describe() {
        return "finish half";
    }
}
