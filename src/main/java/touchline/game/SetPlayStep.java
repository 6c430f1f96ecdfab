package touchline.game;

/**
 * Advances a running set play: READY (robots may position, countdown), PREPARE (stand still,
 * illegally positioned robots removed), EXECUTE (back to normal play with a ball-free countdown)
 * or ABORT (back to normal play at once). The half clock resumes on EXECUTE and ABORT.
 */
public record SetPlayStep(Step step) implements Action {

    /** The referee's set-play commands, in HL AutoRef order. */
    public enum Step { READY, PREPARE, EXECUTE, ABORT }

    @Override
    public boolean isLegal(GameState s) {
        if (s.state != PlayState.PLAYING || !s.secondary.isSetPlay()) {
            return false;
        }
        return switch (step) {
            case READY -> s.setPlayMode == 0;
            case PREPARE -> s.setPlayMode == 1;
            case EXECUTE -> s.setPlayMode >= 1;
            case ABORT -> true;
        };
    }

    @Override
    public void apply(GameState s, long nowMs) {
        switch (step) {
            case READY, PREPARE -> {
                s.setPlayMode = step == Step.READY ? 1 : 2;
                s.setPlayModeSinceMs = nowMs;
            }
            case EXECUTE -> {
                s.endSetPlay();
                s.block(s.params.afterSetPlayBlockSeconds(), nowMs);
            }
            case ABORT -> {
                s.endSetPlay();
                s.block(0, nowMs);
            }
        }
    }

    @Override
    public String describe() {
        return step.name().toLowerCase(java.util.Locale.ROOT);
    }
}
