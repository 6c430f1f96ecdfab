package touchline.game.hsl;

/**
 * Stop Play / Resume: while stopped robots stand still, and the set-play, READY and penalty
 * timers wait (in 6.0.x the game clock too).
 */
public record StopPlay(boolean resume) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return resume ? s.stopped : s.state == HslPlayState.PLAYING && !s.stopped;
    }

    @Override
    public void apply(HslState s) {
        s.stopped = !resume;
    }

    @Override
    public String describe() {
        return resume ? "resume" : "stop";
    }
}
