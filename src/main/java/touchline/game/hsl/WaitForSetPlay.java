package touchline.game.hsl;

/** READY → SET: the robots are in place for the kick-off or penalty kick (also when READY runs out). */
public record WaitForSetPlay() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.state == HslPlayState.READY;
    }

    @Override
    public void apply(HslState s) {
        s.enterSet();
    }

    @Override
    public String describe() {
        return "set";
    }
}
