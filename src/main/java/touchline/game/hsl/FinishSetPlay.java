package touchline.game.hsl;

/** "Ball free": the running set play ends before its time. */
public record FinishSetPlay() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.state == HslPlayState.PLAYING && s.setPlay != null;
    }

    @Override
    public void apply(HslState s) {
        s.endSetPlay();
    }

    @Override
    public String describe() {
        return "ball free";
    }
}
