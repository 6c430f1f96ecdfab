package touchline.game.hsl;

/** The shoot-out shot being taken is over without a goal. */
public record FinishPenaltyShot() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.phase == HslPhase.PENALTY_SHOOT_OUT && s.state == HslPlayState.PLAYING;
    }

    @Override
    public void apply(HslState s) {
        s.endShot();
    }

    @Override
    public String describe() {
        return "missed";
    }
}
